// Writes one recording case of the concealed corpora as a bench would hand it over: case.json
// (the nominal set-up), scan.ply (a synthetic hand-held scan of the hidden truth) and hidden.json
// (what was hidden, for the reader; the diagnosis never sees it).
//   make_concealed_case [--sparse] OUT_DIR LAYOUT SEED EFFECT [EFFECT]
// LAYOUT is one of the corpus's (sag, bend3d, drop, loop) or of the new layouts (steep, s_clips,
// long_sag, twisted3d); EFFECT a shape effect of the catalogue; --sparse scans it with half the
// points, a tenth of the cable unseen and twice the noise.
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "cablefit/formats/json_util.h"
#include "cablefit/formats/ply_reader.h"
#include "concealed_cases.h"

namespace {

using cablefit::Vec3;
using cablefit::json::Json;

Json Vector(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

int Run(int argc, char** argv) {
  cablefit::testing::ScanQuality quality;
  if (argc > 1 && std::string(argv[1]) == "--sparse") {
    quality = cablefit::testing::SparseNoisyScan();
    --argc;
    ++argv;
  }
  if (argc < 5 || argc > 6) {
    std::fprintf(stderr,
                 "usage: make_concealed_case [--sparse] OUT_DIR LAYOUT SEED EFFECT [EFFECT]\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  const std::string layout = argv[2];
  std::mt19937 rng(static_cast<unsigned>(std::stoul(argv[3])));
  const cablefit::testing::Layout* lay = cablefit::testing::FindLayout(layout);
  if (!lay) {
    std::fprintf(stderr, "make_concealed_case: unknown layout %s\n", layout.c_str());
    return 2;
  }
  const cablefit::RodSpec nominal = cablefit::testing::MakeNominal(*lay, rng);
  cablefit::RodSpec truth = nominal;
  Json hidden = Json::array();
  for (int i = 4; i < argc; ++i) {
    const auto clamp = cablefit::testing::HideEffect(argv[i], nominal, false, rng, &truth);
    const auto span = cablefit::testing::HiddenSpan(argv[i], truth);
    hidden.push_back(
        {{"effect", argv[i]},
         {"clamp", clamp ? Json(*clamp) : Json(nullptr)},
         {"interval", span ? Json::array({span->first, span->second}) : Json(nullptr)}});
  }
  const cablefit::testing::ScannedTruth scanned =
      cablefit::testing::ScanTruth(truth, nominal, rng, true, quality);
  if (!scanned.solved) {
    std::fprintf(stderr, "make_concealed_case: the hidden truth was not solved: %s\n",
                 scanned.failure.c_str());
    return 1;
  }
  std::filesystem::create_directories(out);
  Json clamps = Json::array();
  for (const cablefit::SupportSpec& s : nominal.supports)
    clamps.push_back({{"s", s.s},
                      {"position", Vector(s.position)},
                      {"tangent", Vector(s.tangent)},
                      {"normal", Vector(s.normal)}});
  const cablefit::MaterialSpec& m = nominal.material;
  const Json case_json = {{"format", "cable-recording/1"},
                          {"name", out.filename().string()},
                          {"cable",
                           {{"length", nominal.length},
                            {"diameter", m.diameter},
                            {"bending_stiffness", m.bending_stiffness},
                            {"torsional_stiffness", m.torsional_stiffness},
                            {"linear_density", m.linear_density}}},
                          {"gravity", Vector(nominal.gravity)},
                          {"clamps", clamps},
                          {"recordings", Json::array({{{"kind", "scan"}, {"file", "scan.ply"}}})}};
  cablefit::json::WriteJsonFile((out / "case.json").string(), case_json);
  cablefit::json::WriteJsonFile((out / "hidden.json").string(),
                                {{"layout", layout}, {"effects", hidden}});
  cablefit::WritePly((out / "scan.ply").string(), scanned.cloud);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_concealed_case: %s\n", e.what());
    return 1;
  }
}
