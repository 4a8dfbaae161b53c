// Test-only readers for the public force cases: a few-key JSON scanner and a 3-column CSV
// parser (the real readers live in formats/io; core tests must not depend on them).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cablefit/core/rod/recording_case.h"
#include "cablefit/core/rod/rod_spec.h"
#include "test_support.h"

namespace cablefit::testing {

inline std::string ReadText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Position just after `"key":` at or after `from`, or npos.
inline size_t JsonValueAt(const std::string& text, const std::string& key, size_t from = 0) {
  const size_t k = text.find("\"" + key + "\"", from);
  if (k == std::string::npos) return k;
  const size_t colon = text.find(':', k);
  return colon == std::string::npos ? colon : colon + 1;
}

inline std::optional<double> JsonNumber(const std::string& text, const std::string& key,
                                        size_t from = 0) {
  const size_t v = JsonValueAt(text, key, from);
  if (v == std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double d = std::strtod(text.c_str() + v, &end);
  if (end == text.c_str() + v) return std::nullopt;
  return d;
}

inline std::string JsonString(const std::string& text, const std::string& key, size_t from = 0) {
  const size_t v = JsonValueAt(text, key, from);
  if (v == std::string::npos) return "";
  const size_t q1 = text.find('"', v);
  const size_t q2 = text.find('"', q1 + 1);
  return text.substr(q1 + 1, q2 - q1 - 1);
}

inline std::vector<double> JsonArray(const std::string& text, const std::string& key,
                                     size_t from = 0) {
  std::vector<double> out;
  const size_t v = JsonValueAt(text, key, from);
  if (v == std::string::npos) return out;
  size_t pos = text.find('[', v) + 1;
  const size_t close = text.find(']', pos);
  while (pos < close) {
    char* end = nullptr;
    const double d = std::strtod(text.c_str() + pos, &end);
    if (end == text.c_str() + pos) break;
    out.push_back(d);
    pos = static_cast<size_t>(end - text.c_str());
    while (pos < close && (text[pos] == ',' || std::isspace(static_cast<unsigned char>(text[pos]))))
      ++pos;
  }
  return out;
}

inline ForceCurve ReadForceCsv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  ForceCurve c;
  const size_t a = line.find(',');
  const size_t b = line.find(',', a + 1);
  c.x_name = line.substr(a + 1, b - a - 1);
  c.y_name = line.substr(b + 1);
  std::vector<double> xs, ys;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream ss(line);
    std::string f0, f1, f2;
    std::getline(ss, f0, ',');
    std::getline(ss, f1, ',');
    std::getline(ss, f2, ',');
    c.step.push_back(std::stol(f0));
    xs.push_back(std::stod(f1));
    ys.push_back(std::stod(f2));
  }
  c.x = Eigen::Map<Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
  c.y = Eigen::Map<Eigen::VectorXd>(ys.data(), static_cast<Eigen::Index>(ys.size()));
  return c;
}

/// One public case with a single force curve, plus the truth the tests compare against.
struct PublicForceCase {
  std::string name;
  std::string file;
  RodSpec rod;
  ForceTestSpec test;
  ForceCurve curve;
  std::string truth_effect;
  std::optional<double> truth_ratio;
  std::optional<double> truth_loop_area;
  std::vector<double> truth_nominal;     // per recorded row
  std::vector<double> truth_noise_free;  // per recorded row
};

/// Every public case whose case.json records a force_curve (found by content, not by name).
inline std::vector<PublicForceCase> LoadPublicForceCases() {
  std::vector<PublicForceCase> out;
  const auto root = PublicCasesDir();
  std::vector<std::filesystem::path> dirs;
  for (const auto& e : std::filesystem::directory_iterator(root)) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  for (const auto& dir : dirs) {
    const std::string cj = ReadText(dir / "case.json");
    if (cj.find("\"force_curve\"") == std::string::npos) continue;
    PublicForceCase c;
    c.name = dir.filename().string();
    c.file = JsonString(cj, "file", cj.find("\"force_curve\""));
    c.rod.length = *JsonNumber(cj, "length");
    c.rod.material.bending_stiffness = *JsonNumber(cj, "bending_stiffness");
    c.rod.material.torsional_stiffness = *JsonNumber(cj, "torsional_stiffness");
    c.rod.gravity = Vec3::Zero();
    const std::string type = JsonString(cj, "type");
    c.test.type =
        type == "clamped_torsion" ? ForceTestType::kClampedTorsion : ForceTestType::kPinnedBending;
    c.test.prebend = JsonNumber(cj, "prebend").value_or(0.0);
    c.test.max_displacement = JsonNumber(cj, "max_displacement").value_or(0.0);
    c.test.max_angle = JsonNumber(cj, "max_angle").value_or(0.0);
    c.curve = ReadForceCsv(dir / c.file);
    const std::string tj = ReadText(dir / "truth.json");
    c.truth_effect = JsonString(tj, "effect");
    const size_t params = tj.find("\"parameters\"");
    c.truth_ratio = JsonNumber(tj, "ratio", params);
    c.truth_loop_area = JsonNumber(tj, "loop_area", params);
    const size_t curve_at = tj.find("\"" + c.file + "\"", tj.find("\"curves\""));
    c.truth_nominal = JsonArray(tj, "nominal", curve_at);
    c.truth_noise_free = JsonArray(tj, "noise_free", curve_at);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace cablefit::testing
