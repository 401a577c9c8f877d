// ODE aborts the process on its own errors and failed assertions; the program ends instead through the
// handler it sets (the command line's: an internal error, its outputs under way removed, exit 3).

#include "physltl/physics/simulation.h"

#include <gtest/gtest.h>
#include <ode/ode.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void exit_seven(const std::string& message) {
  std::_Exit(message.find("ODE 1: a failure made on purpose") != std::string::npos ? 7 : 8);
}

TEST(EngineFailure, AnAssertionOfTheEngineReachesTheProgramsHandlerInsteadOfAborting) {
  physltl::scenario::World world;
  world.workspace.bounds = {{0, 0}, {2, 2}};
  world.robot.start = {1, 1};
  const physltl::physics::Simulation simulation(world);  // ODE is set up, handlers and all
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    physltl::physics::set_engine_failure_handler(exit_seven);
    dDebug(1, "a failure made on purpose");
    std::_Exit(9);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 7);
}

}  // namespace
