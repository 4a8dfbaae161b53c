#include "kbl_units.h"

#include <charconv>
#include <cmath>
#include <map>

#include "cablefit/core/base/errors.h"
#include "kbl_xml.h"

namespace cablefit::kbl {
namespace {

struct Unit {
  Quantity quantity;
  double to_si;
};

double Prefix(const std::string& prefix, const std::string& unit_id) {
  static const std::map<std::string, double> kPrefix = {
      {"", 1.0},       {"kilo", 1e3},   {"hecto", 1e2},  {"deca", 1e1}, {"deci", 1e-1},
      {"centi", 1e-2}, {"milli", 1e-3}, {"micro", 1e-6}, {"nano", 1e-9}};
  const auto it = kPrefix.find(prefix);
  if (it == kPrefix.end())
    throw InvalidInput("Unit " + unit_id + ": unknown Si_prefix '" + prefix + "'");
  return it->second;
}

Unit ReadUnit(const xmlNode* u) {
  const std::string id = Attribute(u, "id");
  const std::string si = ChildText(u, "Si_unit_name");
  if (!si.empty()) {
    const double p = Prefix(ChildText(u, "Si_prefix"), id);
    const std::string dim = ChildText(u, "Si_dimension");
    if (si == "metre" && (dim.empty() || dim == "none")) return {Quantity::kLength, p};
    if (si == "metre" && dim == "square") return {Quantity::kArea, p * p};
    // The SI base unit of mass is the kilogram; KBL names the gram with prefixes.
    if (si == "gram" && (dim.empty() || dim == "none")) return {Quantity::kMass, 1e-3 * p};
    throw InvalidInput("Unit " + id + ": unsupported unit '" + si + (dim.empty() ? "" : " " + dim) +
                       "'");
  }
  // Units outside SI's base set are named; those a harness file uses for wires.
  static const std::map<std::string, Unit> kNamed = {
      {"GramPerMetre", {Quantity::kLinearDensity, 1e-3}},
      {"KilogramPerMetre", {Quantity::kLinearDensity, 1.0}},
      {"GramPerKilometre", {Quantity::kLinearDensity, 1e-6}},
      {"KilogramPerKilometre", {Quantity::kLinearDensity, 1e-3}},
      {"Millimetre", {Quantity::kLength, 1e-3}}};
  const std::string name = ChildText(u, "Unit_name");
  const auto it = kNamed.find(name);
  if (it == kNamed.end()) {
    throw InvalidInput("Unit " + id + ": " +
                       (name.empty() ? "neither Si_unit_name nor Unit_name given"
                                     : "unknown Unit_name '" + name + "'"));
  }
  return it->second;
}

}  // namespace

const char* ToString(Quantity q) {
  switch (q) {
    case Quantity::kLength:
      return "length";
    case Quantity::kArea:
      return "area";
    case Quantity::kMass:
      return "mass";
    case Quantity::kLinearDensity:
      return "mass per length";
  }
  return "?";
}

double ParseNumber(const std::string& text, const std::string& what) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw InvalidInput(what + ": '" + text + "' is not a number");
  }
  return v;
}

double SiValue(const xmlNode* value_element, Quantity expected,
               const std::unordered_map<std::string, const xmlNode*>& ids) {
  const std::string what = Name(value_element) + " " + Attribute(value_element, "id");
  const std::string unit_id = ChildText(value_element, "Unit_component");
  if (unit_id.empty()) throw InvalidInput(what + ": no Unit_component (the unit is never assumed)");
  const auto it = ids.find(unit_id);
  if (it == ids.end() || Name(it->second) != "Unit") {
    throw InvalidInput(what + ": Unit_component '" + unit_id + "' names no Unit");
  }
  const Unit unit = ReadUnit(it->second);
  if (unit.quantity != expected) {
    throw InvalidInput(what + ": unit " + unit_id + " is a " + ToString(unit.quantity) +
                       ", expected a " + ToString(expected));
  }
  return unit.to_si * ParseNumber(ChildText(value_element, "Value_component"), what);
}

}  // namespace cablefit::kbl
