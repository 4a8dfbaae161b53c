// Prandtl torsion on a Cartesian grid: see section_torsion.h for the method and its sources.
#include "cablefit/core/section/section_torsion.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/section/section.h"

namespace cablefit {
namespace {

// Minimal union-find over grid nodes (nodes joined through void edges share one unknown).
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int Find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void Join(int a, int b) { parent_[Find(a)] = Find(b); }

 private:
  std::vector<int> parent_;
};

// Below this fraction of solid along an edge the edge is treated as void: the coefficient
// h / integral(G) would otherwise reach ~1e9 / G and spoil the factorisation's accuracy.
constexpr double kVoidEdgeFraction = 1e-9;

}  // namespace

CircularPartsRegion::CircularPartsRegion(const std::vector<SectionPart>& parts)
    : parts_(parts), excluded_(FillerExclusions(parts)) {}

namespace {

// The stretches of the line {coordinate `across` = offset} inside the annulus (inner = 0: disc).
void AnnulusIntervals(const Vec2& centre, double outer, double inner, int along, double offset,
                      double g, std::vector<SectionInterval>* out) {
  const double d = offset - centre[1 - along];
  if (std::abs(d) >= outer) return;
  const double c = centre[along];
  const double a_out = std::sqrt(outer * outer - d * d);
  if (std::abs(d) < inner) {
    const double a_in = std::sqrt(inner * inner - d * d);
    out->push_back({c - a_out, c - a_in, g});
    out->push_back({c + a_in, c + a_out, g});
  } else {
    out->push_back({c - a_out, c + a_out, g});
  }
}

// `base` minus the union of `holes` (holes disjoint from each other).
std::vector<SectionInterval> Subtract(std::vector<SectionInterval> base,
                                      std::vector<SectionInterval> holes) {
  std::sort(holes.begin(), holes.end(),
            [](const SectionInterval& a, const SectionInterval& b) { return a.begin < b.begin; });
  std::vector<SectionInterval> out;
  for (const SectionInterval& iv : base) {
    double begin = iv.begin;
    for (const SectionInterval& h : holes) {
      if (h.end <= begin || h.begin >= iv.end) continue;
      if (h.begin > begin) out.push_back({begin, h.begin, iv.shear_modulus});
      begin = std::max(begin, h.end);
    }
    if (begin < iv.end) out.push_back({begin, iv.end, iv.shear_modulus});
  }
  return out;
}

}  // namespace

void CircularPartsRegion::Bounds(Vec2* lo, Vec2* hi) const {
  *lo = Vec2::Constant(INFINITY);
  *hi = Vec2::Constant(-INFINITY);
  for (const SectionPart& p : parts_) {
    *lo = lo->cwiseMin(p.centre - Vec2::Constant(p.outer_radius));
    *hi = hi->cwiseMax(p.centre + Vec2::Constant(p.outer_radius));
  }
}

std::vector<SectionInterval> CircularPartsRegion::LineIntervals(int along, double offset) const {
  std::vector<SectionInterval> out;
  for (size_t i = 0; i < parts_.size(); ++i) {
    const SectionPart& p = parts_[i];
    const double g = p.material.shear_modulus;
    if (excluded_[i].empty()) {
      AnnulusIntervals(p.centre, p.outer_radius, p.inner_radius, along, offset, g, &out);
      continue;
    }
    std::vector<SectionInterval> filler, holes;
    AnnulusIntervals(p.centre, p.outer_radius, p.inner_radius, along, offset, g, &filler);
    for (int k : excluded_[i]) {
      AnnulusIntervals(parts_[k].centre, parts_[k].outer_radius, 0.0, along, offset, 0.0, &holes);
    }
    for (const SectionInterval& iv : Subtract(filler, holes)) out.push_back(iv);
  }
  return out;
}

double CircularPartsRegion::MaxShearModulus() const {
  double g = 0.0;
  for (const SectionPart& p : parts_) g = std::max(g, p.material.shear_modulus);
  return g;
}

void RectangleRegion::Bounds(Vec2* lo, Vec2* hi) const {
  *lo = lo_;
  *hi = hi_;
}

std::vector<SectionInterval> RectangleRegion::LineIntervals(int along, double offset) const {
  const int across = 1 - along;
  if (offset < lo_[across] || offset > hi_[across]) return {};
  return {{lo_[along], hi_[along], shear_modulus_}};
}

bool TorsionOptions::IsValid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (levels < 2 || levels > 6) return fail("torsion levels must be 2..6");
  // Cost grows faster than the cell count: 512 takes 4 s and 0.23 GB, 1024 35 s and 0.73 GB,
  // 2048 over 5 min and over 2.3 GB (measured): beyond 1024 a section file could stall a batch.
  if (finest_cells > 1024) return fail("torsion finest_cells must be <= 1024");
  if (finest_cells < (8 << (levels - 1))) {
    return fail("torsion finest_cells must be >= 8 * 2^(levels-1) = " +
                std::to_string(8 << (levels - 1)));
  }
  return true;
}

const char* ToString(TorsionConvergence c) {
  switch (c) {
    case TorsionConvergence::kAsymptotic: return "asymptotic";
    case TorsionConvergence::kIrregular: return "irregular";
    case TorsionConvergence::kTwoGrids: return "two_grids";
  }
  return "?";
}

std::string TorsionResult::BriefReport() const {
  std::ostringstream s;
  s << "GJ = " << torsional_stiffness << " N m^2 +- " << error_estimate << " ("
    << ToString(convergence) << ", order " << observed_order << ", grids";
  for (const auto& g : grids) s << ' ' << g.cells << ':' << g.torsional_stiffness;
  s << ')';
  return s.str();
}

TorsionGridResult SolvePrandtlTorsionOnGrid(const SectionRegion& region, int cells) {
  const auto start = std::chrono::steady_clock::now();
  Vec2 lo, hi;  // 2 [m] bounding box
  region.Bounds(&lo, &hi);
  CABLEFIT_REQUIRE(cells >= 2 && lo.allFinite() && hi.allFinite() && (hi - lo).maxCoeff() > 0.0,
                   "torsion needs a non-empty region and a grid");
  const Vec2 mid = 0.5 * (lo + hi);  // 2 [m]
  const double h = (hi - lo).maxCoeff() / cells;
  // Nodes at mid + k h, |k| <= half; two padding nodes keep the outside connected all round.
  // Centring on `mid` nests the grids of the refinement study (every coarse node is a fine one).
  const int pad = 2;
  const int half_x = static_cast<int>(std::ceil(0.5 * (hi.x() - lo.x()) / h)) + pad;
  const int half_y = static_cast<int>(std::ceil(0.5 * (hi.y() - lo.y()) / h)) + pad;
  const int nx = 2 * half_x + 1, ny = 2 * half_y + 1;
  const double x0 = mid.x() - half_x * h, y0 = mid.y() - half_y * h;
  auto node = [nx](int i, int j) { return j * nx + i; };
  const int n_nodes = nx * ny;

  // Integral of G along every edge [Pa m]: east edges (i,j)-(i+1,j), north edges (i,j)-(i,j+1).
  std::vector<double> east(n_nodes, 0.0), north(n_nodes, 0.0);
  std::vector<char> solid(n_nodes, 0);
  auto sweep = [&](int along, int count, double origin, int line, double offset,
                   std::vector<double>& edges) {
    for (const SectionInterval& iv : region.LineIntervals(along, offset)) {
      const double a = (iv.begin - origin) / h, b = (iv.end - origin) / h;  // grid units
      const int first = std::max(0, static_cast<int>(std::floor(a)));
      const int last = std::min(count - 2, static_cast<int>(std::floor(b)));
      for (int k = first; k <= last; ++k) {
        const double overlap = std::min(b, k + 1.0) - std::max(a, static_cast<double>(k));
        if (overlap <= 0.0) continue;
        const int n = along == 0 ? node(k, line) : node(line, k);
        edges[n] += iv.shear_modulus * overlap * h;
      }
      for (int k = std::max(0, static_cast<int>(std::ceil(a)));
           k <= std::min(count - 1, static_cast<int>(std::floor(b))); ++k) {
        solid[along == 0 ? node(k, line) : node(line, k)] = 1;
      }
    }
  };
  for (int j = 0; j < ny; ++j) sweep(0, nx, x0, j, y0 + j * h, east);
  for (int i = 0; i < nx; ++i) sweep(1, ny, y0, i, x0 + i * h, north);

  const double void_limit = kVoidEdgeFraction * region.MaxShearModulus() * h;

  // Join nodes across void edges; the padded border is the outside (phi = 0).
  DisjointSets sets(n_nodes);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx && east[node(i, j)] <= void_limit) sets.Join(node(i, j), node(i + 1, j));
      if (j + 1 < ny && north[node(i, j)] <= void_limit) sets.Join(node(i, j), node(i, j + 1));
    }
  }
  const int outside = sets.Find(node(0, 0));
  std::vector<int> unknown_of_root(n_nodes, -1);
  std::vector<int> unknown(n_nodes, -1);  // -1 = outside
  std::vector<int> void_nodes_of;  // per unknown
  int n_unknowns = 0;
  for (int n = 0; n < n_nodes; ++n) {
    const int r = sets.Find(n);
    if (r == outside) continue;
    if (unknown_of_root[r] < 0) {
      unknown_of_root[r] = n_unknowns++;
      void_nodes_of.push_back(0);
    }
    unknown[n] = unknown_of_root[r];
    if (!solid[n]) ++void_nodes_of[unknown[n]];
  }

  TorsionGridResult result;
  result.cells = cells;
  result.spacing = h;
  result.unknowns = n_unknowns;
  for (int count : void_nodes_of) {
    if (count == 0) continue;
    ++result.enclosed_voids;
    result.enclosed_void_area += count * h * h;
  }
  if (n_unknowns == 0) return result;

  // Discrete complementary energy sum_e (h / int_e G)/2 (dphi)^2 - sum_n 2 h^2 phi_n: its
  // minimiser solves K phi = b, and GJ = 2 h^2 sum phi = b . phi.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(5 * static_cast<size_t>(n_unknowns));
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n_unknowns);  // n [m^2], 2 h^2 per node
  auto add_edge = [&](int n, int m, double integral_g) {
    if (integral_g <= void_limit) return;
    const int u = unknown[n], v = unknown[m];
    if (u == v) return;
    const double k = h / integral_g;  // [1/Pa]
    if (u >= 0) triplets.emplace_back(u, u, k);
    if (v >= 0) triplets.emplace_back(v, v, k);
    if (u >= 0 && v >= 0) {
      triplets.emplace_back(u, v, -k);
      triplets.emplace_back(v, u, -k);
    }
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int n = node(i, j);
      if (unknown[n] >= 0) b[unknown[n]] += 2.0 * h * h;
      if (i + 1 < nx) add_edge(n, node(i + 1, j), east[n]);
      if (j + 1 < ny) add_edge(n, node(i, j + 1), north[n]);
    }
  }
  Eigen::SparseMatrix<double> k_matrix(n_unknowns, n_unknowns);  // [1/Pa]
  k_matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(k_matrix);
  CABLEFIT_CHECK(solver.info() == Eigen::Success,
                 "torsion matrix not positive definite (an unknown lacks a path to phi = 0)");
  const Eigen::VectorXd phi = solver.solve(b);  // n [Pa m^2] stress function for unit twist
  result.torsional_stiffness = b.dot(phi);
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

TorsionResult SolvePrandtlTorsion(const SectionRegion& region, const TorsionOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw UsageError("torsion options: " + why);
  TorsionResult r;
  for (int k = options.levels - 1; k >= 0; --k) {
    r.grids.push_back(SolvePrandtlTorsionOnGrid(region, options.finest_cells >> k));
  }
  const size_t n = r.grids.size();
  const double j2 = r.grids[n - 1].torsional_stiffness, j1 = r.grids[n - 2].torsional_stiffness;
  const double d2 = j2 - j1;
  r.finest = r.extrapolated = r.torsional_stiffness = j2;
  if (n == 2) {
    r.convergence = TorsionConvergence::kTwoGrids;
    // Roache's GCI with safety factor 3 and assumed order 2: 3 |d2| / (2^2 - 1).
    r.error_estimate = std::abs(d2);
    return r;
  }
  const double d1 = j1 - r.grids[n - 3].torsional_stiffness;
  const double order = (d1 * d2 > 0.0) ? std::log2(d1 / d2) : 0.0;
  if (d1 * d2 > 0.0 && order >= 0.5 && order <= 4.0) {
    r.convergence = TorsionConvergence::kAsymptotic;
    r.observed_order = order;
    const double step = d2 / (std::pow(2.0, order) - 1.0);
    r.extrapolated = r.torsional_stiffness = j2 + step;
    r.error_estimate = 1.25 * std::abs(step);
  } else {
    r.convergence = TorsionConvergence::kIrregular;
    r.observed_order = order;
    r.error_estimate = std::max(std::abs(d2), std::abs(d1) / 4.0);
  }
  return r;
}

}  // namespace cablefit
