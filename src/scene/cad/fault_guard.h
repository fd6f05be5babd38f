// fault_guard.h - a crash inside Open CASCADE (its readers on damaged files) turned into an
// error the caller can put into words, instead of the end of the process.
//
// Open CASCADE is built to survive its own faults: where it expects trouble it opens an error
// handler (OCC_CATCH_SIGNALS) that a signal converted by its handler jumps to, and it goes on,
// for example reporting the entity it was translating as failed. That conversion is off
// unless a program installs Open CASCADE's signal handlers for the whole process (OSD::
// SetSignal), which would also take over Ctrl+C and every crash outside Open CASCADE. The guard
// converts only the faults of threads inside it, and of threads inside Open CASCADE's own
// handlers while some guard is open (its mesher's workers); every other fault goes to the
// handler that was there before (the default, which ends the process, or AddressSanitizer's
// report), as if there were no guard.
#pragma once

#include <functional>

namespace scene {

// Runs `body` on this thread. A SIGSEGV, SIGBUS, SIGFPE or SIGILL raised by this thread while
// it runs (a stack overflow included: the handler runs on an alternate stack) goes to the
// innermost Open CASCADE error handler open on this thread. Where that is Open CASCADE's own,
// it handles the fault as it was written to, and `body` goes on; where it is the guard's, the
// signal number is returned. 0: `body` returned. Other exceptions pass through.
//
// After a jump the frames between the fault and the handler are abandoned without their
// destructors, so whatever they owned leaks: the price of carrying on after a foreign crash,
// and why the guard should wrap calls into Open CASCADE, never the caller's own data.
int runGuarded(const std::function<void()>& body);

// "segmentation fault", "bus error", "arithmetic fault" or "illegal instruction".
const char* faultName(int signal);

} // namespace scene
