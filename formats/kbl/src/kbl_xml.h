// The few libxml2 calls the KBL reader needs, behind a small RAII document and node helpers, so
// no libxml2 type leaks into the public header. Parsing is safe for untrusted files: no network,
// no DTD loading, no entity substitution (no XXE), libxml2's default size limits.
#pragma once

#include <libxml/tree.h>

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace cablefit::kbl {

struct XmlDocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using XmlDoc = std::unique_ptr<xmlDoc, XmlDocFree>;

/// Parses `bytes`; throws InvalidInput "not XML: <libxml2's message> (line N)".
XmlDoc ParseXml(const std::string& bytes);

/// Local name of an element ("Segment" for <kbl:Segment>).
std::string Name(const xmlNode* n);
/// Attribute value, "" when absent.
std::string Attribute(const xmlNode* n, const char* name);
/// Text content, whitespace trimmed.
std::string Text(const xmlNode* n);
/// Element children, all or those named `name`.
std::vector<const xmlNode*> Children(const xmlNode* n, const char* name = nullptr);
/// The first child named `name`, nullptr when none.
const xmlNode* Child(const xmlNode* n, const char* name);
/// Trimmed text of the first child named `name`, "" when none.
std::string ChildText(const xmlNode* n, const char* name);
/// Whitespace-separated tokens (KBL id lists such as "Segment_1 Segment_2").
std::vector<std::string> Tokens(const std::string& text);

/// Every element with an `id` attribute, by id (the first when an id repeats).
std::unordered_map<std::string, const xmlNode*> IndexIds(const xmlNode* root);

}  // namespace cablefit::kbl
