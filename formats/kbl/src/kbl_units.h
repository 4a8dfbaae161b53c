// KBL quantities: a Value_component with a Unit_component pointing at a <Unit> element
// (Si_prefix + Si_unit_name [+ Si_dimension], or a Unit_name such as "GramPerMetre"). Converted
// to SI by what the file declares; a unit that is missing, unknown or of the wrong kind (a mass
// where a length is expected) is an error naming the element.
#pragma once

#include <libxml/tree.h>

#include <string>
#include <unordered_map>

namespace cablefit::kbl {

enum class Quantity { kLength, kArea, kMass, kLinearDensity };

/// "length", "area", ...
const char* ToString(Quantity q);

/// The value of a KBL numerical element (`Value_component` + `Unit_component`) in SI units
/// (m, m^2, kg, kg/m). Throws InvalidInput naming `what` (the element's id).
double SiValue(const xmlNode* value_element, Quantity expected,
               const std::unordered_map<std::string, const xmlNode*>& ids);

/// Parses a decimal number; throws InvalidInput "<what>: '<text>' is not a number".
double ParseNumber(const std::string& text, const std::string& what);

}  // namespace cablefit::kbl
