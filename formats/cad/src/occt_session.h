// Process-wide OCCT set-up shared by the reader, the writer and the sample tool.
#pragma once

namespace cablefit {

/// OCCT works in millimetres (xstep.cascade.unit = MM): multiply by this to get metres.
inline constexpr double kMetresPerOcctUnit = 1e-3;

/// Removes OCCT's default stdout printers once (they print coloured transfer statistics) and
/// initialises the STEP/IGES XDE controllers. Safe to call repeatedly.
void InitOcctSession();

}  // namespace cablefit
