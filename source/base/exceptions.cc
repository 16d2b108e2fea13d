#include <deal.II/base/exceptions.h>

#include <fvfsi/base/exceptions.h>

#include <sstream>

namespace fvfsi
{
  std::string concise_message(const std::exception& e)
  {
    const auto* d = dynamic_cast<const dealii::ExceptionBase*>(&e);
    if (!d)
      return e.what();
    std::ostringstream info;
    d->print_info(info);
    std::string s = info.str();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
      s.pop_back();
    const auto start = s.find_first_not_of(" \n");
    return start == std::string::npos ? s : s.substr(start);
  }

  std::string three_digits(const double x)
  {
    std::ostringstream text;
    text.precision(3);
    text << x;
    return text.str();
  }
} // namespace fvfsi
