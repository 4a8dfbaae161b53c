#include "occt_session.h"

#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Controller.hxx>
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

}  // namespace cablefit
