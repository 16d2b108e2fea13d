// Bad input stays a clear error (issue 15, item 6): every shipped .prm file of prm/ is run on
// mutated copies, and each run must end either normally (exit 0, a summary.json whose numbers are
// all finite) or with a non-zero exit and a message that names the parameter. Never by a signal,
// a hang or a non-finite number; and a summary.json written, also by a failed run, must parse as
// JSON (Boost's property_tree parser).
//
// Mutations of a `set Key = value` line: the value replaced by nan, its numbers negated, set to
// zero or to 1e300, the value empty, a value of the wrong type (a word for a number, a number for
// a word), the line deleted; and for every patch name in a value: a patch that does not exist;
// for the FSI interfaces: a patch that exists but is not at the other side's interface. The
// message must name the mutated parameter; after a deleted line, which leaves the parameter its
// documented default (a valid input of another case), it must name some parameter.
//
// Each run is `fvfsi MUTATED.prm --steps 2` in this process (fvfsi::run_application, what
// main() calls): two time steps, or two iterations of each loop of a steady run; starting a
// process costs 0.45 s of MPI start-up alone, more than most of the runs. A signal (a crash) or a
// run longer than `hang_seconds` ends this test with the mutation named (the handlers below).
//
// The test samples one mutation kind per line (rotating through the kinds, so that each kind
// meets every section) plus every patch mutation; `prm_mutations --all` runs every kind on every
// line (doc/results/prm_mutations.sh writes that table). The output (counts per file, and any
// failure) is compared exactly: it holds no computed number.
#include <fvfsi/app/application.h>

#define BOOST_BIND_GLOBAL_PLACEHOLDERS // Boost 1.74's property_tree still includes boost/bind.hpp
#include <boost/property_tree/json_parser.hpp>

#include "../test_utilities.h"

#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <unistd.h>

using namespace fvfsi_test;
namespace fs = std::filesystem;

namespace
{
  constexpr unsigned int hang_seconds = 120;

  /// Cases whose shipped meshes are too large for the sweep (the thick plate: 45 056 + 16 384
  /// cells, and 8 million after a deleted `Solid mesh/Global refinements`, whose default is 3; the
  /// Turek-Hron channels of up to 47 160 cells and the elastic tube: FSI3 41 s, FSI2 18 s, the
  /// tube 37 s, CFD3 11 s of the 152 s for all files) run on coarse meshes (the channel and flag
  /// of tests/coupling/fsi3_coarse, the tube refined once): these --set overrides, each left out
  /// when its own line is the mutated one. On the tube refined once (faces of about 2 x 4 mm) the
  /// outer surface of the 1 mm wall lies within FaceInterpolation's reach of the fluid's
  /// interface; its mutation `interface elsewhere` asserts that it is refused all the same (it
  /// faces the same way as the fluid's interface).
  using Overrides = std::vector<std::pair<std::string, std::string>>;
  const Overrides turek_hron_fsi_coarse = {{"Mesh/Generator arguments", "12"},
                                           {"Solid mesh/Generator arguments", "20: 2"}};
  const std::map<std::string, Overrides> coarse_meshes = {
    {"thick_plate.prm",
     {{"Mesh/Generator arguments", "0.05"}, {"Solid mesh/Generator arguments", "0.05"}}},
    {"elastic_tube.prm",
     {{"Mesh/Global refinements", "1"}, {"Solid mesh/Global refinements", "1"}}},
    {"turek_hron_cfd3.prm", {{"Mesh/Generator arguments", "12"}}},
    {"turek_hron_fsi2.prm", turek_hron_fsi_coarse},
    {"turek_hron_fsi3.prm", turek_hron_fsi_coarse},
    {"turek_hron_fsi3_fast.prm", turek_hron_fsi_coarse}};

  /// What the signal handlers print: the mutation being run.
  char current_mutation[1024] = "";

  extern "C" void on_signal(const int signal)
  {
    const char* what = signal == SIGALRM ? "hang (longer than the alarm)" : strsignal(signal);
    const char* mutation = current_mutation;
    for (const char* text : {"prm_mutations: FAILED by ", what, " in: ", mutation, "\n"})
    {
      const ssize_t n = write(2, text, std::strlen(text));
      (void)n;
    }
    _exit(1);
  }

  /// One `set Key = value` line of a .prm file.
  struct SetLine
  {
    unsigned int line;   // index into the file's lines
    std::string path;    // "Section/Sub/Key"
    std::string key;     // "Key"
    std::string value;   // as written
    std::string section; // "Section/Sub" ("" at the top level)
  };

  struct PrmFile
  {
    std::vector<std::string> lines;
    std::vector<SetLine> sets;
  };

  std::string trim(const std::string& s)
  {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  }

  PrmFile read_prm(std::istream& in)
  {
    PrmFile prm;
    std::vector<std::string> sections;
    for (std::string line; std::getline(in, line);)
    {
      const std::string t = trim(line);
      if (t.rfind("subsection ", 0) == 0)
        sections.push_back(trim(t.substr(11)));
      else if (t == "end")
        sections.pop_back();
      else if (t.rfind("set ", 0) == 0)
      {
        const auto eq = t.find('=');
        SetLine s;
        s.line = prm.lines.size();
        s.key = trim(t.substr(4, eq - 4));
        s.value = trim(t.substr(eq + 1));
        for (const auto& name : sections)
          s.section += (s.section.empty() ? "" : "/") + name;
        s.path = (s.section.empty() ? "" : s.section + "/") + s.key;
        prm.sets.push_back(s);
      }
      prm.lines.push_back(line);
    }
    return prm;
  }

  /// `value` with every number in it replaced by f(number): "0.03: 2: true" -> "-0.03: -2: true".
  template <class F>
  std::string map_numbers(const std::string& value, F f)
  {
    static const std::regex number(R"((^|[^A-Za-z0-9_.])([0-9]+\.?[0-9]*([eE][-+]?[0-9]+)?))");
    std::string out;
    auto begin = value.cbegin();
    for (std::smatch m; std::regex_search(begin, value.cend(), m, number); begin = m[0].second)
      out += m.prefix().str() + m[1].str() + f(m[2].str());
    return out + std::string(begin, value.cend());
  }

  bool has_number(const std::string& value)
  {
    return map_numbers(value, [](const std::string&) { return "#"; }) != value;
  }

  struct Mutation
  {
    std::string kind;
    const SetLine* target;
    std::string value; // the new value (unused for `deleted`)
  };

  const std::vector<std::string> value_kinds = {"nan",   "negative",   "zero",   "huge",
                                                "empty", "wrong type", "deleted"};

  Mutation make_mutation(const std::string& kind, const SetLine& s)
  {
    Mutation m{kind, &s, ""};
    if (kind == "nan")
      m.value = "nan";
    else if (kind == "negative")
      m.value = has_number(s.value) ? map_numbers(s.value, [](auto x) { return "-" + x; }) : "-1";
    else if (kind == "zero")
      m.value = has_number(s.value) ? map_numbers(s.value, [](auto) { return "0"; }) : "0";
    else if (kind == "huge")
      m.value = has_number(s.value) ? map_numbers(s.value, [](auto) { return "1e300"; }) : "1e300";
    else if (kind == "wrong type")
      m.value = has_number(s.value) ? "abc" : "1.5";
    return m;
  }

  /// The patch names a file defines: those of its `Patch names` lines, and the generators'
  /// defaults.
  std::set<std::string> patch_names(const PrmFile& prm)
  {
    std::set<std::string> names = {"left", "right", "bottom", "top", "back", "front"};
    static const std::regex entry(R"([0-9]+\s*:\s*([A-Za-z_][A-Za-z0-9_]*))");
    for (const auto& s : prm.sets)
      if (s.key == "Patch names")
        for (std::sregex_iterator i(s.value.begin(), s.value.end(), entry), e; i != e; ++i)
          names.insert((*i)[1].str());
    return names;
  }

  /// The mutations a file gets: `all` kinds per line or one (rotating with `offset`), plus the
  /// patch mutations.
  std::vector<Mutation> mutations(const PrmFile& prm, const bool all, const unsigned int offset)
  {
    std::vector<Mutation> list;
    for (unsigned int i = 0; i < prm.sets.size(); ++i)
    {
      const SetLine& s = prm.sets[i];
      if (s.key == "Output directory")
        continue; // the test's own: every run writes into a directory of its own
      if (all)
        for (const auto& kind : value_kinds)
          list.push_back(make_mutation(kind, s));
      else
        list.push_back(make_mutation(value_kinds[(i + offset) % value_kinds.size()], s));
    }
    // A patch name that does not exist, in each value that names a patch.
    const std::set<std::string> patches = patch_names(prm);
    static const std::regex word(R"([A-Za-z_][A-Za-z0-9_]*)");
    for (const auto& s : prm.sets)
    {
      if (s.key == "Patch names")
        continue;
      for (std::sregex_iterator i(s.value.begin(), s.value.end(), word), e; i != e; ++i)
        if (patches.count((*i)[0].str()) &&
            (i->position() == 0 || s.value[i->position() - 1] != '*'))
        {
          Mutation m{"unknown patch", &s,
                     s.value.substr(0, i->position()) + "no_such_patch" +
                       s.value.substr(i->position() + i->length())};
          list.push_back(m);
          break;
        }
    }
    // An interface patch that exists but does not face the other side's interface.
    for (const auto& s : prm.sets)
      if (s.section == "Coupling" && (s.key == "Fluid interface" || s.key == "Solid interface"))
      {
        const std::string mesh = s.key == "Fluid interface" ? "Mesh" : "Solid mesh";
        for (const auto& names : prm.sets)
          if (names.path == mesh + "/Patch names")
          {
            std::smatch m;
            std::string rest = names.value;
            static const std::regex entry(R"([0-9]+\s*:\s*([A-Za-z_][A-Za-z0-9_]*))");
            for (; std::regex_search(rest, m, entry); rest = m.suffix().str())
              if (m[1].str() != s.value)
              {
                list.push_back({"interface elsewhere", &s, m[1].str()});
                break;
              }
          }
      }
    return list;
  }

  std::string mutated_text(const PrmFile& prm, const Mutation& m, const std::string& output)
  {
    std::ostringstream text;
    for (unsigned int i = 0; i < prm.lines.size(); ++i)
      if (i != m.target->line)
        text << prm.lines[i] << "\n";
      else if (m.kind != "deleted")
        text << "set " << m.target->key << " = " << m.value << "\n";
    // The test's own settings, last so that they hold: a directory per run, no plots (python).
    text << "set Output directory = " << output << "\nset Plot history = false\n";
    return text.str();
  }

  std::string lower(std::string s)
  {
    for (auto& c : s)
      c = std::tolower(c);
    return s;
  }

  /// "Section/Key" of every parameter fvfsi declares (from `fvfsi --print-parameters`).
  std::vector<std::string> declared_parameters()
  {
    std::ostringstream text, error;
    fvfsi::run_application({"--print-parameters"}, text, error);
    std::istringstream in(text.str());
    std::vector<std::string> paths;
    for (const auto& s : read_prm(in).sets)
      if (!s.section.empty())
        paths.push_back(s.path);
    return paths;
  }

  /// "" if the run ended as it must, else why not. `parameters`: every declared "Section/Key".
  std::string judge(const Mutation& m, const int code, const std::string& message,
                    const std::string& output, const std::vector<std::string>& parameters)
  {
    // Whatever the end, a summary.json written must be JSON (a failed run's error message may
    // span lines: they must arrive escaped).
    if (fs::exists(output + "/summary.json"))
      try
      {
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(output + "/summary.json", tree);
      }
      catch (const std::exception& e)
      {
        return std::string("summary.json is not JSON: ") + e.what();
      }
    if (code == 0)
    {
      std::ifstream in(output + "/summary.json");
      const std::string json((std::istreambuf_iterator<char>(in)), {});
      if (json.find("\"completed\"") == std::string::npos)
        return "exit 0 without a completed summary.json";
      // fvfsi writes a non-finite number as null; a bare nan or inf would not be JSON at all.
      static const std::regex non_finite(R"([:\[,]\s*(null|-?nan|-?inf))", std::regex::icase);
      if (std::regex_search(json, non_finite))
        return "a non-finite number in summary.json";
      return "";
    }
    const std::string text = lower(message);
    if (text.find(lower(m.target->key)) != std::string::npos ||
        text.find("no_such_patch") != std::string::npos)
      return "";
    // A deleted line gives its parameter the documented default, a valid input of another case
    // (no Scene: the Poisson problem); should that case fail, its message must still point at a
    // parameter to change.
    if (m.kind == "deleted")
      for (const auto& path : parameters)
        if (text.find(lower(path)) != std::string::npos)
          return "";
    return "the message does not name " + m.target->path;
  }
} // namespace

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Arguments: `--all` (every kind on every line), `--verbose` (each run and its message on
  // stdout), a word (only the files whose name has it).
  bool all = false, verbose = false;
  std::string only;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--all")
      all = true;
    else if (std::string(argv[i]) == "--verbose")
      verbose = true;
    else
      only = argv[i];
  for (const int s : {SIGSEGV, SIGFPE, SIGABRT, SIGBUS, SIGILL, SIGALRM})
    std::signal(s, on_signal);
  std::ofstream out = open_output();

  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(FVFSI_SOURCE_DIR) / "prm"))
    if (entry.path().extension() == ".prm")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());

  const std::vector<std::string> parameters = declared_parameters();
  unsigned int total = 0, failures = 0;
  for (unsigned int f = 0; f < files.size(); ++f)
  {
    if (files[f].filename().string().find(only) == std::string::npos)
      continue;
    std::ifstream in(files[f]);
    const PrmFile prm = read_prm(in);
    unsigned int n = 0, ran = 0, rejected = 0;
    for (const Mutation& m : mutations(prm, all, f))
    {
      const std::string name = files[f].stem().string() + "_" + std::to_string(n++);
      const std::string output = "runs/" + name;
      const std::string description = files[f].filename().string() + ": " + m.target->path + ": " +
                                      m.kind + (m.kind == "deleted" ? "" : " `" + m.value + "`");
      std::snprintf(current_mutation, sizeof current_mutation, "%s", description.c_str());
      std::ofstream(name + ".prm") << mutated_text(prm, m, output);

      std::ostringstream log, error;
      std::streambuf* const cout_buffer = std::cout.rdbuf(log.rdbuf()); // progress lines
      alarm(hang_seconds);
      std::vector<std::string> arguments = {name + ".prm", "--steps", "2"};
      if (const auto it = coarse_meshes.find(files[f].filename().string());
          it != coarse_meshes.end())
        for (const auto& [key, value] : it->second)
          if (m.target->path != key)
            arguments.insert(arguments.end(), {"--set", key + "=" + value});
      const int code = fvfsi::run_application(arguments, log, error);
      alarm(0);
      std::cout.rdbuf(cout_buffer);

      const std::string verdict = judge(m, code, error.str(), output, parameters);
      if (verbose)
        std::cout << description << "\n  exit " << code << " " << error.str() << std::endl;
      if (!verdict.empty())
      {
        ++failures;
        out << "FAILED: " << description << ": " << verdict << "\n  exit " << code << ": "
            << error.str() << "\n";
      }
      else
        (code == 0 ? ran : rejected) += 1;
      fs::remove_all(output);
      fs::remove(name + ".prm");
      ++total;
    }
    out << files[f].filename().string() << ": " << n << " mutations: " << ran << " ran, "
        << rejected << " stopped with a message naming the parameter\n";
  }
  out << "total: " << total << " mutations, " << failures << " failures\n";
}
