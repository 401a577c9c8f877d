#pragma once

namespace physltl::physics {

// ODE needs one library initialisation per process and its own data per thread; call this before
// touching ODE on any thread.
void ensure_ode_ready_on_this_thread();

// How many messages ODE's solver has sent from this thread: each says it failed on a step's constraints.
unsigned long long solver_messages_on_this_thread();

}  // namespace physltl::physics
