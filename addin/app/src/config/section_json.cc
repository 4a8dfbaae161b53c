#include "cablefit/app/config/section_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {
namespace {

using json::FieldReader;
using json::Json;

using json::RequireKnownKeys;

std::string OptionalString(const FieldReader& r, const std::string& key, std::string fallback) {
  return r.Has(key) ? r.RequireString(key) : fallback;
}

bool OptionalBool(const FieldReader& r, const std::string& key) {
  if (!r.Has(key)) return false;
  const Json& v = r.object().at(key);
  if (!v.is_boolean()) r.Fail(key, "must be true or false, got " + json::Describe(v));
  return v.get<bool>();
}

int RequireInt(const FieldReader& r, const std::string& key) {
  const double v = r.RequireNumber(key);
  if (v != std::floor(v) || std::abs(v) > 1e9) r.Fail(key, "must be an integer");
  return static_cast<int>(v);
}

Vec2 RequireVec2(const FieldReader& r, const std::string& key) {
  const Json& v = r.RequireArray(key);
  if (v.size() != 2) r.Fail(key, "must be an array of two numbers [x, y] in metres");
  const std::string name = json::JoinKey(r.where(), key);
  return Vec2(json::NumberValue(v[0], r.file(), name + "[0]"),
              json::NumberValue(v[1], r.file(), name + "[1]"));
}

// E, G or nu (not both), density: one linear-elastic material.
SectionMaterial ParseMaterial(const FieldReader& r, const std::string& name) {
  RequireKnownKeys(r, {"E", "G", "nu", "density", "source", "note"});
  SectionMaterial m;
  m.name = name;
  m.youngs_modulus = r.RequirePositive("E");
  if (r.Has("G") == r.Has("nu")) r.FailHere("needs exactly one of G or nu");
  if (r.Has("G")) {
    m.shear_modulus = r.RequirePositive("G");
  } else {
    const double nu = r.RequireNumber("nu");
    if (nu <= -1.0 || nu >= 0.5) r.Fail("nu", "must lie in (-1, 0.5)");
    m.shear_modulus = m.youngs_modulus / (2.0 * (1.0 + nu));
  }
  m.density = r.RequireNonNegative("density");
  return m;
}

// Resolves names against the section file's own "materials", then the library's.
class Catalogue {
 public:
  Catalogue(const Json& root, const std::string& file) : file_(file) {
    const FieldReader r(root, file);
    if (r.Has("materials")) local_ = &r.RequireObject("materials");
    if (r.Has("library")) {
      std::filesystem::path p = r.RequireString("library");
      if (p.is_relative()) p = std::filesystem::path(file).parent_path() / p;
      library_path_ = p.lexically_normal().string();
      library_ = json::ReadJsonFile(library_path_);
      const FieldReader lib(library_, library_path_);
      if (lib.Has("format") && lib.RequireString("format") != "cablefit-materials/1") {
        lib.Fail("format", "must be \"cablefit-materials/1\"");
      }
      RequireKnownKeys(lib, {"format", "notes", "sources", "materials", "wires", "layers"});
    }
  }

  const std::string& library_path() const { return library_path_; }

  SectionMaterial Material(const std::string& name, const FieldReader& user,
                           const std::string& key) const {
    if (local_ && local_->contains(name)) {
      return ParseMaterial(FieldReader(*local_, file_, "materials").Child(name), name);
    }
    if (const Json* entry = LibraryEntry("materials", name)) {
      return ParseMaterial(FieldReader(*entry, library_path_, "materials." + name), name);
    }
    user.Fail(key, "names unknown material '" + name + "'" +
                       (library_path_.empty() ? " (no library given)" : ""));
  }

  // A material given by name or inline as an object.
  SectionMaterial MaterialField(const FieldReader& r, const std::string& key,
                                const std::string& fallback_name) const {
    const Json& v = r.object().contains(key) ? r.object().at(key) : Json();
    if (v.is_string()) return Material(v.get<std::string>(), r, key);
    if (v.is_object()) return ParseMaterial(r.Child(key), fallback_name);
    if (v.is_null()) r.Fail(key, "is missing");
    r.Fail(key, "must be a material name or an object {E, G or nu, density}");
  }

  // The library object `group.name`, or nullptr.
  const Json* LibraryEntry(const std::string& group, const std::string& name) const {
    if (!library_.is_object() || !library_.contains(group)) return nullptr;
    const Json& g = library_.at(group);
    if (!g.is_object() || !g.contains(name)) return nullptr;
    return &g.at(name);
  }

  FieldReader LibraryReader(const std::string& group, const std::string& name,
                            const FieldReader& user, const std::string& key) const {
    const Json* entry = LibraryEntry(group, name);
    if (!entry) {
      user.Fail(key, "names unknown library " + group.substr(0, group.size() - 1) + " '" + name +
                         "'" + (library_path_.empty() ? " (no library given)" : ""));
    }
    return FieldReader(*entry, library_path_, group + "." + name);
  }

 private:
  std::string file_;
  const Json* local_ = nullptr;
  std::string library_path_;
  Json library_;
};

// A library wire: conductor disc + insulation annulus. A stranded conductor of n strands of
// diameter d inside a circle of diameter D is taken to bend and twist with its strands slipping
// freely (each strand about its own axis): E_eff = E n d^4 / D^4, G_eff likewise, and its mass is
// that of the copper only (rho n d^2 / D^2). This is a lower bound; friction and compaction put
// real conductors above it (see samples/materials notes).
void AddLibraryWire(const Catalogue& cat, const FieldReader& comp, const std::string& name,
                    const Vec2& position, SectionInput* in) {
  const std::string wire = comp.RequireString("wire");
  const FieldReader w = cat.LibraryReader("wires", wire, comp, "wire");
  RequireKnownKeys(w, {"conductor_diameter", "strands", "strand_diameter", "conductor_material",
                       "outer_diameter", "insulation_material", "cross_section_mm2",
                       "insulation_wall", "source", "note"});
  const double d_cond = w.RequirePositive("conductor_diameter");
  const double d_out = w.RequirePositive("outer_diameter");
  if (d_out <= d_cond) w.Fail("outer_diameter", "must exceed conductor_diameter");
  SectionMaterial conductor = cat.Material(w.RequireString("conductor_material"), w,
                                           "conductor_material");
  if (w.Has("strands")) {
    const int n = RequireInt(w, "strands");
    const double d = w.RequirePositive("strand_diameter");
    if (n < 1) w.Fail("strands", "must be >= 1");
    const double fill = n * d * d / (d_cond * d_cond);
    if (fill > 1.0) w.Fail("strands", "strands do not fit in conductor_diameter");
    const double bend = n * std::pow(d / d_cond, 4);
    conductor.youngs_modulus *= bend;
    conductor.shear_modulus *= bend;
    conductor.density *= fill;
    conductor.name += " (" + std::to_string(n) + " strands, free slip)";
    const std::string note =
        "library wires: stranded conductors bend and twist with free slip between strands "
        "(E_eff = E n d^4 / D^4, mass of the copper only), a lower bound; friction, compaction "
        "and the insulation's grip make real conductors stiffer";
    if (std::find(in->notes.begin(), in->notes.end(), note) == in->notes.end()) {
      in->notes.push_back(note);
    }
  }
  SectionPart core;
  core.name = name + "/conductor";
  core.centre = position;
  core.outer_radius = 0.5 * d_cond;
  core.material = conductor;
  SectionPart insulation;
  insulation.name = name + "/insulation";
  insulation.centre = position;
  insulation.outer_radius = 0.5 * d_out;
  insulation.inner_radius = 0.5 * d_cond;
  insulation.material =
      cat.Material(w.RequireString("insulation_material"), w, "insulation_material");
  in->spec.parts.push_back(core);
  in->spec.parts.push_back(insulation);
}

void AddComponent(const Catalogue& cat, const FieldReader& c, size_t index, SectionInput* in) {
  RequireKnownKeys(c, {"name", "position", "wire", "outer_radius", "inner_radius", "material",
                       "fills_gaps"});
  const std::string name = OptionalString(c, "name", "component " + std::to_string(index + 1));
  const Vec2 position = RequireVec2(c, "position");
  if (c.Has("wire")) {
    for (const char* k : {"outer_radius", "inner_radius", "material", "fills_gaps"}) {
      if (c.Has(k)) c.Fail(k, "cannot be combined with a library wire");
    }
    AddLibraryWire(cat, c, name, position, in);
    return;
  }
  SectionPart p;
  p.name = name;
  p.centre = position;
  p.outer_radius = c.RequirePositive("outer_radius");
  p.inner_radius = c.Has("inner_radius") ? c.RequireNonNegative("inner_radius") : 0.0;
  p.material = cat.MaterialField(c, "material", name);
  p.fills_gaps = OptionalBool(c, "fills_gaps");
  in->spec.parts.push_back(p);
}

// Layers wrap everything before them unless given an explicit centre / inner radius.
void AddLayer(const Catalogue& cat, const FieldReader& l, size_t index, SectionInput* in) {
  RequireKnownKeys(l, {"name", "layer", "centre", "inner_radius", "outer_radius", "thickness",
                       "material", "fills_gaps"});
  const std::string name = OptionalString(l, "name", "layer " + std::to_string(index + 1));
  SectionPart p;
  p.name = name;
  p.fills_gaps = OptionalBool(l, "fills_gaps");
  double thickness = NAN, inner = NAN, outer = NAN;
  if (l.Has("layer")) {
    for (const char* k : {"material", "thickness", "outer_radius", "inner_radius"}) {
      if (l.Has(k)) l.Fail(k, "cannot be combined with a library layer");
    }
    const FieldReader e = cat.LibraryReader("layers", l.RequireString("layer"), l, "layer");
    RequireKnownKeys(e, {"kind", "thickness", "inner_diameter", "outer_diameter", "material",
                         "source", "note"});
    p.material = cat.Material(e.RequireString("material"), e, "material");
    if (e.Has("thickness")) {
      thickness = e.RequirePositive("thickness");
    } else {
      inner = 0.5 * e.RequirePositive("inner_diameter");
      outer = 0.5 * e.RequirePositive("outer_diameter");
    }
  } else {
    p.material = cat.MaterialField(l, "material", name);
    if (l.Has("inner_radius")) inner = l.RequireNonNegative("inner_radius");
    if (l.Has("thickness") == l.Has("outer_radius")) {
      l.FailHere("needs exactly one of thickness or outer_radius");
    }
    if (l.Has("thickness")) thickness = l.RequirePositive("thickness");
    if (l.Has("outer_radius")) outer = l.RequirePositive("outer_radius");
  }
  Vec2 wrap_centre = Vec2::Zero();
  double wrap_radius = 0.0;
  if (!in->spec.parts.empty()) {
    SmallestEnclosingCircle(in->spec.parts, &wrap_centre, &wrap_radius);
  }
  p.centre = l.Has("centre") ? RequireVec2(l, "centre") : wrap_centre;
  if (std::isnan(inner)) {
    inner = 0.0;
    for (const SectionPart& q : in->spec.parts) {
      inner = std::max(inner, (q.centre - p.centre).norm() + q.outer_radius);
    }
  }
  if (std::isnan(outer)) outer = inner + thickness;
  p.inner_radius = p.fills_gaps ? 0.0 : inner;
  p.outer_radius = outer;
  if (p.outer_radius <= inner) {
    l.FailHere("outer radius " + std::to_string(outer) + " m does not exceed inner radius " +
               std::to_string(inner) + " m (the bundle does not fit)");
  }
  in->spec.parts.push_back(p);
}

}  // namespace

SectionInput ReadSectionFile(const std::string& path) {
  const Json root = json::ReadJsonFile(path);
  const FieldReader r(root, path);
  RequireKnownKeys(r, {"format", "name", "library", "materials", "components", "layers",
                       "torsion", "note"});
  if (r.Has("format") && r.RequireString("format") != "cablefit-section/1") {
    r.Fail("format", "must be \"cablefit-section/1\"");
  }
  const Catalogue cat(root, path);
  SectionInput in;
  in.library = cat.library_path();
  const Json& components = r.RequireArray("components");
  if (components.empty()) r.Fail("components", "is empty");
  for (size_t i = 0; i < components.size(); ++i) {
    AddComponent(cat, FieldReader(components[i], path, json::IndexKey("components", i)), i, &in);
  }
  if (r.Has("layers")) {
    const Json& layers = r.RequireArray("layers");
    for (size_t i = 0; i < layers.size(); ++i) {
      AddLayer(cat, FieldReader(layers[i], path, json::IndexKey("layers", i)), i, &in);
    }
  }
  if (r.Has("torsion")) {
    const FieldReader t = r.Child("torsion");
    RequireKnownKeys(t, {"finest_cells", "levels"});
    if (t.Has("finest_cells")) in.torsion.finest_cells = RequireInt(t, "finest_cells");
    if (t.Has("levels")) in.torsion.levels = RequireInt(t, "levels");
  }
  std::string why;
  if (!in.torsion.IsValid(&why)) r.FailHere(why);  // why names the torsion field
  try {
    ValidateSection(in.spec);
  } catch (const FileError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw FileError(path, e.what());
  }
  return in;
}

Json SectionResultToJson(const SectionResult& res, const SectionInput& input,
                         const std::string& input_path) {
  const double deg = 180.0 / std::numbers::pi;
  Json out;
  out["format"] = "cablefit-section-result/1";
  out["input"] = input_path;
  if (!input.library.empty()) out["library"] = input.library;
  out["area"] = res.area;
  out["linear_density"] = res.linear_density;
  out["axial_stiffness"] = res.axial_stiffness;
  out["modulus_centre"] = {res.modulus_centre.x(), res.modulus_centre.y()};
  out["outer_diameter"] = res.outer_diameter;
  out["enclosing_centre"] = {res.enclosing_centre.x(), res.enclosing_centre.y()};
  Json bending;
  bending["matrix"] = json::MatrixToJson(res.bending_matrix);
  bending["max"] = res.bending_max;
  bending["min"] = res.bending_min;
  bending["principal_angle"] = res.principal_angle;
  bending["principal_angle_deg"] = res.principal_angle * deg;
  bending["stiff_axis"] = {std::cos(res.principal_angle), std::sin(res.principal_angle)};
  bending["unbonded"] = res.bending_unbonded;
  out["bending"] = bending;
  if (res.coaxial.applies) {
    out["coaxial"] = {{"bending_stiffness_eq4", res.coaxial.bending_stiffness},
                      {"torsional_stiffness_eq9", res.coaxial.torsional_stiffness}};
  } else {
    out["coaxial"] = nullptr;
  }
  Json torsion;
  torsion["stiffness"] = res.torsion.torsional_stiffness;
  torsion["error_estimate"] = res.torsion.error_estimate;
  torsion["relative_error_estimate"] =
      json::NumberOrNull(res.torsion.error_estimate / res.torsion.torsional_stiffness);
  torsion["convergence"] = ToString(res.torsion.convergence);
  torsion["observed_order"] = res.torsion.observed_order;
  torsion["finest"] = res.torsion.finest;
  torsion["extrapolated"] = res.torsion.extrapolated;
  torsion["unbonded"] = res.torsion_unbonded;
  Json grids = Json::array();
  for (const TorsionGridResult& g : res.torsion.grids) {
    grids.push_back({{"cells", g.cells},
                     {"spacing", g.spacing},
                     {"unknowns", g.unknowns},
                     {"enclosed_voids", g.enclosed_voids},
                     {"enclosed_void_area", g.enclosed_void_area},
                     {"stiffness", g.torsional_stiffness},
                     {"seconds", g.seconds}});
  }
  torsion["grids"] = grids;
  out["torsion"] = torsion;
  const MaterialSpec m = SectionToMaterial(res);
  out["material"] = {{"bending_stiffness", m.bending_stiffness},
                     {"bending_ratio", m.bending_ratio},
                     {"principal_angle", m.principal_angle},
                     {"torsional_stiffness", m.torsional_stiffness},
                     {"linear_density", m.linear_density},
                     {"diameter", m.diameter}};
  Json parts = Json::array();
  for (const SectionPart& p : input.spec.parts) {
    parts.push_back({{"name", p.name},
                     {"centre", {p.centre.x(), p.centre.y()}},
                     {"outer_radius", p.outer_radius},
                     {"inner_radius", p.inner_radius},
                     {"fills_gaps", p.fills_gaps},
                     {"material", p.material.name},
                     {"E", p.material.youngs_modulus},
                     {"G", p.material.shear_modulus},
                     {"density", p.material.density}});
  }
  out["parts"] = parts;
  Json notes = Json::array();
  for (const std::string& n : input.notes) notes.push_back(n);
  for (const std::string& n : res.notes) notes.push_back(n);
  out["notes"] = notes;
  return out;
}

}  // namespace cablefit::addin
