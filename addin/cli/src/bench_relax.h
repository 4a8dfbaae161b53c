// `cablefit bench` figures of whole runs: `relax` of harness files end to end (every stage,
// pictures and STEP included) and whole `cablefit` processes (start-up included).
#pragma once

#include <string>
#include <vector>

namespace cablefit::addin {

/// Relaxes each file as `cablefit relax FILE --out SCRATCH` does, `reps` times; prints per file
/// the run with the median total: its seconds per stage, the largest stage's share, and the
/// figures of its largest network (segments, elements, Newton iterations, estimated error).
int BenchRelaxFiles(const std::vector<std::string>& files, int reps);

/// Times whole processes of the `cablefit` beside this executable, `reps` times each (median and
/// fastest): `cablefit --version` and `cablefit simulate` of a 0.755 m cable sagging between two
/// clamps (the built-in bench cable, written as a case).
int BenchProcesses(int reps);

}  // namespace cablefit::addin
