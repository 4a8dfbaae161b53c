#include "kbl_xml.h"

#include <libxml/parser.h>
#include <libxml/xmlerror.h>

#include <climits>
#include <sstream>

#include "cablefit/core/base/errors.h"

namespace cablefit::kbl {
namespace {

std::string Trim(const std::string& s) {
  const char* ws = " \t\r\n";
  const size_t a = s.find_first_not_of(ws);
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(ws) - a + 1);
}

void IndexInto(const xmlNode* n, std::unordered_map<std::string, const xmlNode*>* out) {
  for (const xmlNode* c = n; c; c = c->next) {
    if (c->type != XML_ELEMENT_NODE) continue;
    const std::string id = Attribute(c, "id");
    if (!id.empty()) out->emplace(id, c);
    IndexInto(c->children, out);
  }
}

}  // namespace

XmlDoc ParseXml(const std::string& bytes) {
  if (bytes.size() > static_cast<size_t>(INT_MAX))
    throw InvalidInput("too large for the XML parser");
  // No XML_PARSE_NOENT (entities stay references), no DTDLOAD/DTDVALID (nothing fetched or
  // expanded from a DTD), NONET (never the network), no HUGE (libxml2 keeps its depth and size
  // limits).
  const int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING;
  xmlResetLastError();
  XmlDoc doc(
      xmlReadMemory(bytes.data(), static_cast<int>(bytes.size()), "kbl.xml", nullptr, options));
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    std::string why = e && e->message ? Trim(e->message) : "unreadable";
    if (e && e->line > 0) why += " (line " + std::to_string(e->line) + ")";
    throw InvalidInput("not XML: " + why);
  }
  return doc;
}

std::string Name(const xmlNode* n) {
  return n && n->name ? reinterpret_cast<const char*>(n->name) : "";
}

std::string Attribute(const xmlNode* n, const char* name) {
  for (const xmlAttr* a = n->properties; a; a = a->next) {
    if (a->name && std::string(reinterpret_cast<const char*>(a->name)) == name && a->children &&
        a->children->content) {
      return reinterpret_cast<const char*>(a->children->content);
    }
  }
  return "";
}

std::string Text(const xmlNode* n) {
  std::string s;
  for (const xmlNode* c = n->children; c; c = c->next) {
    if ((c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) && c->content)
      s += reinterpret_cast<const char*>(c->content);
  }
  return Trim(s);
}

std::vector<const xmlNode*> Children(const xmlNode* n, const char* name) {
  std::vector<const xmlNode*> out;
  for (const xmlNode* c = n->children; c; c = c->next) {
    if (c->type == XML_ELEMENT_NODE && (!name || Name(c) == name)) out.push_back(c);
  }
  return out;
}

const xmlNode* Child(const xmlNode* n, const char* name) {
  for (const xmlNode* c = n->children; c; c = c->next) {
    if (c->type == XML_ELEMENT_NODE && Name(c) == name) return c;
  }
  return nullptr;
}

std::string ChildText(const xmlNode* n, const char* name) {
  const xmlNode* c = Child(n, name);
  return c ? Text(c) : "";
}

std::vector<std::string> Tokens(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

std::unordered_map<std::string, const xmlNode*> IndexIds(const xmlNode* root) {
  std::unordered_map<std::string, const xmlNode*> out;
  IndexInto(root, &out);
  return out;
}

}  // namespace cablefit::kbl
