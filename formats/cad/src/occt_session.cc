#include "occt_session.h"

#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <OSD.hxx>
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
}  // namespace

ScopedOcctSignals::ScopedOcctSignals() {
  for (int k = 0; k < kCount; ++k) sigaction(kSignals[k], nullptr, &saved_[k]);
  OSD::SetSignal(OSD_SignalMode_SetUnhandled, false);
}

ScopedOcctSignals::~ScopedOcctSignals() {
  for (int k = 0; k < kCount; ++k) sigaction(kSignals[k], &saved_[k], nullptr);
}

}  // namespace cablefit
