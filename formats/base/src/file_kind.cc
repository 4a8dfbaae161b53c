#include "cablefit/formats/file_kind.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cablefit {
namespace {

constexpr std::size_t kSniffBytes = 4096;

std::string Head(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::string head(kSniffBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

std::string TrimmedStart(const std::string& text) {
  std::size_t i = 0;
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) i = 3;  // UTF-8 byte order mark
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.substr(i);
}

bool IsIges(const std::string& head) {
  const std::size_t end = head.find('\n');
  std::string line = head.substr(0, end);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line.size() >= 73 && line.size() <= 82 && line[72] == 'S';
}

FileKind Ply(const std::string& head) {
  // The header ends with "end_header"; a face element with a positive count makes it a mesh.
  std::istringstream lines(head.substr(0, head.find("end_header")));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string element, name;
    long count = 0;
    if (words >> element >> name >> count && element == "element" && name == "face" && count > 0)
      return FileKind::kPlyMesh;
  }
  return FileKind::kPlyPoints;
}

bool IsBinaryStl(const std::string& path, const std::string& head) {
  if (head.size() < 84) return false;
  std::uint32_t triangles = 0;
  for (int k = 3; k >= 0; --k)
    triangles = (triangles << 8) | static_cast<unsigned char>(head[80 + static_cast<std::size_t>(k)]);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return !ec && triangles > 0 && size == 84 + 50 * static_cast<std::uintmax_t>(triangles);
}

}  // namespace

FileKind SniffFileKind(const std::string& path) {
  const std::string head = Head(path);
  if (head.empty()) return FileKind::kUnknown;
  const std::string text = TrimmedStart(head);
  if (text.rfind("ISO-10303-21", 0) == 0) return FileKind::kStep;
  if (IsIges(head)) return FileKind::kIges;
  if (text.rfind("ply", 0) == 0 && text.size() > 3 && (text[3] == '\n' || text[3] == '\r'))
    return Ply(text);
  if (IsBinaryStl(path, head)) return FileKind::kStl;
  if (text.rfind("solid", 0) == 0 && text.find("facet") != std::string::npos) return FileKind::kStl;
  if (!text.empty() && (text[0] == '{' || text[0] == '[')) return FileKind::kJson;
  // The root tag follows the XML declaration and processing instructions within the first few
  // hundred bytes (the VW samples: five lines of them).
  if (!text.empty() && text[0] == '<' && text.find("KBL_container") != std::string::npos)
    return FileKind::kKbl;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("v ", 0) == 0) return FileKind::kObj;
  return FileKind::kUnknown;
}

std::string DescribeFileKind(FileKind kind) {
  switch (kind) {
    case FileKind::kStep: return "a STEP file";
    case FileKind::kIges: return "an IGES file";
    case FileKind::kJson: return "a JSON file";
    case FileKind::kPlyMesh: return "a PLY mesh";
    case FileKind::kPlyPoints: return "a PLY point cloud (no faces)";
    case FileKind::kStl: return "an STL mesh";
    case FileKind::kObj: return "an OBJ mesh";
    case FileKind::kKbl: return "a KBL harness file";
    case FileKind::kUnknown: break;
  }
  return "";
}

}  // namespace cablefit
