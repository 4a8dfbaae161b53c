// Process-wide OCCT set-up shared by the reader, the writer and the sample tool.
#pragma once

#include <mutex>

namespace cablefit {

/// OCCT works in millimetres (xstep.cascade.unit = MM): multiply by this to get metres.
inline constexpr double kMetresPerOcctUnit = 1e-3;

/// Removes OCCT's default stdout printers once (they print coloured transfer statistics) and
/// initialises the STEP/IGES XDE controllers. Safe to call repeatedly.
void InitOcctSession();

/// OCCT's IGES file parser (igesread.c and its part list) keeps the file being parsed in static
/// variables: two IGES reads at once in one process corrupt each other and crash (seen with four
/// threads of a batch). Every IGES read and transfer holds this lock; STEP's parser is reentrant.
std::mutex& IgesReaderMutex();

}  // namespace cablefit
