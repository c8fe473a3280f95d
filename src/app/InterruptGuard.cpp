#include "app/InterruptGuard.h"

namespace tabletop {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void onSignal(int signal) { received = signal; }

}  // namespace

InterruptGuard::InterruptGuard() {
  received = 0;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, &previousInt_);
  sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
}

bool InterruptGuard::requested() const { return received != 0; }

int InterruptGuard::signal() const { return received; }

}  // namespace tabletop
