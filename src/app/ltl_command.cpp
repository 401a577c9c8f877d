#include "command.h"

namespace physltl::app {

CommandRunner add_ltl_command(CLI::App& app) {
  auto formula = std::make_shared<std::string>();
  app.add_option("formula", *formula, "The formula, e.g. 'F(p1 & F p2)'")->required();
  return [formula]() -> int { throw BadInput("the ltl command is not implemented yet"); };
}

}  // namespace physltl::app
