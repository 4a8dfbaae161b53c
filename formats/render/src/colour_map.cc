// Viridis table: every fifth entry of matplotlib's 256-entry `_viridis_data` (CC0, Stéfan van der
// Walt and Nathaniel Smith, "A Better Default Colormap for Matplotlib", SciPy 2015), linearly
// interpolated; the map is smooth enough that the sub-sampling error is below one 8-bit step.
#include "cablefit/formats/colour_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cablefit {
namespace {

constexpr std::array<std::array<double, 3>, 52> kViridis = {{
    {0.267004, 0.004874, 0.329415},
    {0.273809, 0.031497, 0.358853},
    {0.278791, 0.062145, 0.386592},
    {0.281924, 0.089666, 0.412415},
    {0.283197, 0.115680, 0.436115},
    {0.282623, 0.140926, 0.457517},
    {0.280255, 0.165693, 0.476498},
    {0.276194, 0.190074, 0.493001},
    {0.270595, 0.214069, 0.507052},
    {0.263663, 0.237631, 0.518762},
    {0.255645, 0.260703, 0.528312},
    {0.246811, 0.283237, 0.535941},
    {0.237441, 0.305202, 0.541921},
    {0.227802, 0.326594, 0.546532},
    {0.218130, 0.347432, 0.550038},
    {0.208623, 0.367752, 0.552675},
    {0.199430, 0.387607, 0.554642},
    {0.190631, 0.407061, 0.556089},
    {0.182256, 0.426184, 0.557120},
    {0.174274, 0.445044, 0.557792},
    {0.166617, 0.463708, 0.558119},
    {0.159194, 0.482237, 0.558073},
    {0.151918, 0.500685, 0.557587},
    {0.144759, 0.519093, 0.556572},
    {0.137770, 0.537492, 0.554906},
    {0.131172, 0.555899, 0.552459},
    {0.125394, 0.574318, 0.549086},
    {0.121148, 0.592739, 0.544641},
    {0.119423, 0.611141, 0.538982},
    {0.121380, 0.629492, 0.531973},
    {0.128087, 0.647749, 0.523491},
    {0.140210, 0.665859, 0.513427},
    {0.157851, 0.683765, 0.501686},
    {0.180653, 0.701402, 0.488189},
    {0.208030, 0.718701, 0.472873},
    {0.239374, 0.735588, 0.455688},
    {0.274149, 0.751988, 0.436601},
    {0.311925, 0.767822, 0.415586},
    {0.352360, 0.783011, 0.392636},
    {0.395174, 0.797475, 0.367757},
    {0.440137, 0.811138, 0.340967},
    {0.487026, 0.823929, 0.312321},
    {0.535621, 0.835785, 0.281908},
    {0.585678, 0.846661, 0.249897},
    {0.636902, 0.856542, 0.216620},
    {0.688944, 0.865448, 0.182725},
    {0.741388, 0.873449, 0.149561},
    {0.793760, 0.880678, 0.120005},
    {0.845561, 0.887322, 0.099702},
    {0.896320, 0.893616, 0.096335},
    {0.945636, 0.899815, 0.112838},
    {0.993248, 0.906157, 0.143936},
}};

std::uint8_t ToByte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

Rgb Viridis(double t) {
  if (!std::isfinite(t)) t = 0.0;
  const double x = std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), kViridis.size() - 2);
  const double f = x - static_cast<double>(i);
  const auto& a = kViridis[i];
  const auto& b = kViridis[i + 1];
  return {ToByte(a[0] + f * (b[0] - a[0])), ToByte(a[1] + f * (b[1] - a[1])),
          ToByte(a[2] + f * (b[2] - a[2]))};
}

double ColourScale::Normalised(double value) const {
  if (!std::isfinite(value) || !(max > min)) return 0.0;
  return std::clamp((value - min) / (max - min), 0.0, 1.0);
}

bool ColourScale::IsValid(std::string* why) const {
  if (std::isfinite(min) && std::isfinite(max) && max > min) return true;
  if (why) *why = "colour scale needs finite min < max";
  return false;
}

}  // namespace cablefit
