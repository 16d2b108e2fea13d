#include <deal.II/base/utilities.h>

#include <fvfsi/app/parameters.h>
#include <fvfsi/app/steady_settings.h>
#include <fvfsi/base/exceptions.h>

#include <cctype>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// deal.II's form of an entry path in get_entries_wrongly_not_set(): the sections and the
    /// key joined by '.', every character but a letter or digit written as _ and two hex digits.
    std::string mangled_path(const std::string& path)
    {
      static const char hex[] = "0123456789abcdef";
      std::string out;
      std::string::size_type begin = 0;
      while (true)
      {
        const auto slash = path.find('/', begin);
        for (const char c : path.substr(begin, slash - begin))
          if (std::isalnum(static_cast<unsigned char>(c)))
            out += c;
          else
            out += {'_', hex[static_cast<unsigned char>(c) / 16],
                    hex[static_cast<unsigned char>(c) % 16]};
        if (slash == std::string::npos)
          return out;
        out += '.';
        begin = slash + 1;
      }
    }

    /// One steady setting: the parameter, its steady value and why.
    struct Setting
    {
      std::string path, value, reason;
    };
  } // namespace

  bool given(const ParameterHandler& prm, const std::string& path)
  {
    return prm.get_entries_wrongly_not_set().count(mangled_path(path)) == 0;
  }

  std::vector<std::string> apply_steady_settings(AllParameters& parameters)
  {
    using Scene = RunParameters::Scene;
    const Scene scene = parameters.run.scene;
    if (!(scene == Scene::fluid || scene == Scene::fsi) || parameters.fluid.transient)
      return {};
    // The values prm/turek_hron_fsi1.prm and prm/turek_hron_cfd2.prm were measured with
    // (doc/results/performance.md, section 16, has the table before and after).
    std::vector<Setting> table = {
      {"Fluid/Consistent pressure coupling", "true",
       "SIMPLEC: stable at Momentum relaxation 0.95 where SIMPLE's correction is too strong"},
      {"Fluid momentum solver/Residual reduction", "0.1",
       "a pseudo time step needs only a rough solve, the pseudo steps converge the rest"},
      {"Fluid pressure solver/Residual reduction", "0.01", "as the momentum solve"},
      {"Fluid pressure solver/Corrector residual reduction", "0.1", "as the momentum solve"}};
    if (scene == Scene::fsi)
      table.push_back({"Fluid/Steady tolerance",
                       three_digits(0.1 * parameters.fsi.coupling.tolerance),
                       "0.1 x Coupling/Tolerance: every coupling iteration converges the fluid "
                       "an order below the interface residual, not to 1e-8"});
    std::vector<std::string> taken;
    for (const Setting& s : table)
      if (!given(parameters.prm, s.path))
      {
        apply_override(parameters.prm, s.path + "=" + s.value);
        taken.push_back(s.path + " = " + s.value + " (" + s.reason + ")");
      }
    return taken;
  }
} // namespace fvfsi
