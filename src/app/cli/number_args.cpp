#include "number_args.h"

#include "physltl/scenario/world.h"

#include <cerrno>
#include <cstdlib>
#include <string>

namespace physltl::app {

CLI::Validator number_in(double lo, double hi, bool lo_allowed) {
  return CLI::Validator(
      [lo, hi, lo_allowed](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
        const auto problem = scenario::number_problem(value, lo, hi, lo_allowed);
        return problem ? "'" + text + "' " + *problem : "";
      },
      "NUMBER");
}

CLI::Validator seed_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 20 && text.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) std::strtoull(text.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE) return "a seed is a whole number from 0 to 18446744073709551615, got '" + text + "'";
        return "";
      },
      "SEED");
}

}  // namespace physltl::app
