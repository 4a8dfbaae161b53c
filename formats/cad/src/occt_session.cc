#include "occt_session.h"

#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <OSD.hxx>
#include <atomic>
#include <csignal>
#include <mutex>

namespace cablefit {

void InitOcctSession() {
  static std::once_flag once;
  std::call_once(once, [] {
    const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
    // Copy first: removing while iterating the live sequence would skip printers.
    Message_SequenceOfPrinters printers = messenger->Printers();
    for (Message_SequenceOfPrinters::Iterator it(printers); it.More(); it.Next()) {
      messenger->RemovePrinter(it.Value());
    }
    STEPCAFControl_Controller::Init();
    IGESControl_Controller::Init();
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  });
}

std::mutex& OcctExchangeMutex() {
  static std::mutex mutex;
  return mutex;
}

namespace {
// Every signal OSD::SetSignal may take over on Linux: all are given back.
constexpr int kSignals[ScopedOcctSignals::kCount] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGHUP,
                                                     SIGINT, SIGQUIT, SIGTRAP, SIGSYS, SIGTERM, SIGXCPU};
// The faults a damaged file causes; each is recorded, then handed to OCCT's handler.
constexpr int kFaults = 4;  // the first kFaults of kSignals

struct sigaction g_occt[kFaults];
std::atomic<int> g_caught{0};

void RecordFault(int sig, siginfo_t* info, void* context) {
  g_caught.store(sig);
  for (int k = 0; k < kFaults; ++k) {
    if (kSignals[k] != sig) continue;
    if (g_occt[k].sa_flags & SA_SIGINFO) {
      g_occt[k].sa_sigaction(sig, info, context);  // longjmps to OCCT's OCC_CATCH_SIGNALS
    } else if (g_occt[k].sa_handler != SIG_DFL && g_occt[k].sa_handler != SIG_IGN) {
      g_occt[k].sa_handler(sig);
    }
  }
  ::signal(sig, SIG_DFL);  // OCCT did not take it: die of it as before
  ::raise(sig);
}
}  // namespace

ScopedOcctSignals::ScopedOcctSignals() {
  g_caught.store(0);
  for (int k = 0; k < kCount; ++k) sigaction(kSignals[k], nullptr, &saved_[k]);
  OSD::SetSignal(OSD_SignalMode_SetUnhandled, false);
  // Only the faults are OCCT's to catch: Ctrl-C or a kill during a transfer must still end the
  // process, not fail one entity and let the read go on without it.
  for (int k = kFaults; k < kCount; ++k) sigaction(kSignals[k], &saved_[k], nullptr);
  for (int k = 0; k < kFaults; ++k) {
    struct sigaction now {};
    sigaction(kSignals[k], nullptr, &now);
    const bool occt = (now.sa_flags & SA_SIGINFO) ? now.sa_sigaction != saved_[k].sa_sigaction
                                                  : now.sa_handler != saved_[k].sa_handler;
    if (!occt) continue;  // a handler was there before (a sanitizer's): it stays in charge
    g_occt[k] = now;
    struct sigaction wrap = now;
    wrap.sa_flags = now.sa_flags | SA_SIGINFO;
    wrap.sa_sigaction = RecordFault;
    sigaction(kSignals[k], &wrap, nullptr);
  }
}

ScopedOcctSignals::~ScopedOcctSignals() {
  for (int k = 0; k < kCount; ++k) sigaction(kSignals[k], &saved_[k], nullptr);
}

int ScopedOcctSignals::caught() const { return g_caught.load(); }

}  // namespace cablefit
