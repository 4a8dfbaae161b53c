// Process-wide OCCT set-up shared by the reader, the writer and the sample tool.
#pragma once

#include <csignal>
#include <mutex>

namespace cablefit {

/// OCCT works in millimetres (xstep.cascade.unit = MM): multiply by this to get metres.
inline constexpr double kMetresPerOcctUnit = 1e-3;

/// Removes OCCT's default stdout printers once (they print coloured transfer statistics) and
/// initialises the STEP/IGES XDE controllers. Safe to call repeatedly.
void InitOcctSession();

/// OCCT's data exchange is not reentrant: the IGES parser (igesread.c and its part list) keeps
/// the file being parsed in static variables, and STEP's transfer sets the length unit in a
/// process-wide singleton (StepData_GlobalFactors, in STEPControl_ActorRead::PrepareUnits) that
/// other transfers read, as the writers read the Interface_Static parameters. Two reads at once
/// crashed (IGES: in iges_nextpart; STEP: in PrepareUnits, about 1 run in 10 of four threads
/// reading STEP and IGES), and could scale one file by another's unit. Every STEP and IGES read,
/// transfer and write holds this lock; what comes after the transfer (recognition, sweeps) runs
/// in parallel.
std::mutex& OcctExchangeMutex();

/// While it lives, an access violation inside OCCT becomes a Standard_Failure at OCCT's nearest
/// OCC_CATCH_SIGNALS (its transfer code guards each entity so), instead of ending the process,
/// and caught() says it happened: OCCT's IGES boundary and curve analysis read and write out of
/// bounds on some damaged files, and whether that crashed depended on the heap's layout. After
/// such a fault the read is not to be trusted (memory may be overwritten): the reader fails the
/// file as the crash probe does. Signals that already have a handler (a sanitizer's, a
/// debugger's) keep it; the previous handlers are back afterwards. Taken under
/// OcctExchangeMutex, so only one is alive at a time.
class ScopedOcctSignals {
 public:
  ScopedOcctSignals();
  ~ScopedOcctSignals();
  ScopedOcctSignals(const ScopedOcctSignals&) = delete;
  ScopedOcctSignals& operator=(const ScopedOcctSignals&) = delete;
  static constexpr int kCount = 12;
  /// The signal number of the first fault OCCT caught while this lived, or 0.
  int caught() const;

 private:
  struct sigaction saved_[kCount];
};

}  // namespace cablefit
