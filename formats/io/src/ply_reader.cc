// PLY reader after the format description by Greg Turk (1994),
// http://paulbourke.net/dataformats/ply/ — header of `element`/`property` lines, then the
// elements in header order, either whitespace-separated text or packed binary.
#include "cablefit/formats/ply_reader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/input_file.h"
#include "cablefit/formats/number_text.h"

namespace cablefit {
namespace {

enum class Encoding { kAscii, kLittle, kBig };

enum class ScalarType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

bool ScalarTypeFromName(const std::string& name, ScalarType* type) {
  static const struct {
    const char* name;
    ScalarType type;
  } kNames[] = {{"char", ScalarType::kInt8},     {"int8", ScalarType::kInt8},
                {"uchar", ScalarType::kUint8},   {"uint8", ScalarType::kUint8},
                {"short", ScalarType::kInt16},   {"int16", ScalarType::kInt16},
                {"ushort", ScalarType::kUint16}, {"uint16", ScalarType::kUint16},
                {"int", ScalarType::kInt32},     {"int32", ScalarType::kInt32},
                {"uint", ScalarType::kUint32},   {"uint32", ScalarType::kUint32},
                {"float", ScalarType::kFloat32}, {"float32", ScalarType::kFloat32},
                {"double", ScalarType::kFloat64}, {"float64", ScalarType::kFloat64}};
  for (const auto& entry : kNames)
    if (name == entry.name) {
      *type = entry.type;
      return true;
    }
  return false;
}

std::size_t SizeOf(ScalarType type) {
  switch (type) {
    case ScalarType::kInt8:
    case ScalarType::kUint8: return 1;
    case ScalarType::kInt16:
    case ScalarType::kUint16: return 2;
    case ScalarType::kInt32:
    case ScalarType::kUint32:
    case ScalarType::kFloat32: return 4;
    case ScalarType::kFloat64: return 8;
  }
  return 0;
}

bool IsFloating(ScalarType type) {
  return type == ScalarType::kFloat32 || type == ScalarType::kFloat64;
}

struct Property {
  std::string name;
  ScalarType type = ScalarType::kFloat32;
  bool is_list = false;
  ScalarType count_type = ScalarType::kUint8;  // list only
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;  // first byte after "end_header\n"
};

// A header is a few hundred bytes; one that has not ended after this many is not a header.
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;

std::vector<std::string> Tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  std::string token;
  while (in >> token) out.push_back(token);
  return out;
}

Header ParseHeader(const std::string& data, const std::string& path) {
  if (data.rfind("ply\n", 0) != 0 && data.rfind("ply\r\n", 0) != 0)
    throw FileError(path, "not a PLY file (first line is not 'ply')");
  Header header;
  std::size_t pos = 0;
  int line_no = 0;
  bool have_format = false;
  bool ended = false;
  while (pos < data.size()) {
    const std::size_t eol = data.find('\n', pos);
    if (eol == std::string::npos) break;
    std::string line = data.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = "header line " + std::to_string(line_no);
    if (line_no == 1) continue;  // the magic, checked above
    const std::vector<std::string> t = Tokens(line);
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      ended = true;
      break;
    }
    if (t[0] == "format") {
      if (t.size() != 3) throw FileError(path, where + ": malformed format line");
      if (t[1] == "ascii") header.encoding = Encoding::kAscii;
      else if (t[1] == "binary_little_endian") header.encoding = Encoding::kLittle;
      else if (t[1] == "binary_big_endian") header.encoding = Encoding::kBig;
      else throw FileError(path, where + ": unknown format '" + t[1] + "'");
      if (t[2] != "1.0") throw FileError(path, where + ": unsupported PLY version '" + t[2] + "'");
      have_format = true;
    } else if (t[0] == "element") {
      long count = -1;
      if (t.size() != 3 || !ParseInteger(t[2], &count) || count < 0)
        throw FileError(path, where + ": malformed element line '" + line + "'");
      header.elements.push_back({t[1], static_cast<std::uint64_t>(count), {}});
    } else if (t[0] == "property") {
      if (header.elements.empty())
        throw FileError(path, where + ": property before any element");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        p.is_list = true;
        if (!ScalarTypeFromName(t[2], &p.count_type) || !ScalarTypeFromName(t[3], &p.type))
          throw FileError(path, where + ": unknown list type in '" + line + "'");
        if (IsFloating(p.count_type))
          throw FileError(path, where + ": list count type must be an integer type");
        p.name = t[4];
      } else if (t.size() == 3) {
        if (!ScalarTypeFromName(t[1], &p.type))
          throw FileError(path, where + ": unknown property type '" + t[1] + "'");
        p.name = t[2];
      } else {
        throw FileError(path, where + ": malformed property line '" + line + "'");
      }
      header.elements.back().properties.push_back(p);
    } else {
      throw FileError(path, where + ": unexpected keyword '" + t[0] + "' (missing end_header?)");
    }
  }
  if (!ended) throw FileError(path, "missing end_header (header never ends)");
  if (!have_format) throw FileError(path, "missing format line in header");
  header.body_offset = pos;
  return header;
}

// ---- binary ----

class BinaryCursor {
 public:
  BinaryCursor(const std::string& data, std::size_t pos, Encoding enc, const std::string& path)
      : data_(data), pos_(pos), path_(path),
        swap_((enc == Encoding::kLittle) != (std::endian::native == std::endian::little)) {}

  double Read(ScalarType type, const char* what) {
    const std::size_t n = SizeOf(type);
    if (data_.size() - pos_ < n)
      throw FileError(path_, std::string("truncated: file ends inside ") + what);
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    if (swap_)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (type) {
      case ScalarType::kInt8: return static_cast<double>(static_cast<std::int8_t>(b[0]));
      case ScalarType::kUint8: return b[0];
      case ScalarType::kInt16: return Get<std::int16_t>(b);
      case ScalarType::kUint16: return Get<std::uint16_t>(b);
      case ScalarType::kInt32: return Get<std::int32_t>(b);
      case ScalarType::kUint32: return Get<std::uint32_t>(b);
      case ScalarType::kFloat32: return Get<float>(b);
      case ScalarType::kFloat64: return Get<double>(b);
    }
    return 0.0;
  }

  void Skip(std::uint64_t bytes, const char* what) {
    if (data_.size() - pos_ < bytes)
      throw FileError(path_, std::string("truncated: file ends inside ") + what);
    pos_ += bytes;
  }

 private:
  template <typename T>
  static double Get(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return static_cast<double>(v);
  }
  const std::string& data_;
  std::size_t pos_;
  const std::string& path_;
  bool swap_;
};

// ---- ascii ----

class TextCursor {
 public:
  TextCursor(const std::string& data, std::size_t pos, const std::string& path)
      : data_(data), pos_(pos), path_(path) {}

  std::string_view Next(const char* what) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (pos_ >= data_.size())
      throw FileError(path_, std::string("truncated: file ends before ") + what);
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    return std::string_view(data_).substr(start, pos_ - start);
  }

  double Number(const char* what) {
    const std::string_view token = Next(what);
    double value = 0.0;
    if (ParseDouble(token, &value) == ParsedNumber::kNotANumber)
      throw FileError(path_, std::string(what) + ": '" + std::string(token) + "' is not a number");
    return value;
  }

 private:
  const std::string& data_;
  std::size_t pos_;
  const std::string& path_;
};

// Smallest number of body bytes one instance of `e` can take: guards allocation against header
// counts the file cannot hold.
std::uint64_t MinBytesPerItem(const Element& e, Encoding enc) {
  std::uint64_t bytes = 0;
  for (const Property& p : e.properties) {
    if (enc == Encoding::kAscii) bytes += 2;  // a digit and a separator, list counts alike
    else bytes += SizeOf(p.is_list ? p.count_type : p.type);
  }
  return bytes;
}

std::uint64_t ListCount(double raw, const std::string& path, const char* what) {
  if (!(raw >= 0) || raw != std::floor(raw) || raw > 1e9)
    throw FileError(path, std::string(what) + ": invalid list length " + FormatDouble(raw));
  return static_cast<std::uint64_t>(raw);
}

}  // namespace

PointCloud ReadPly(const std::string& path) {
  const std::uint64_t file_size = CheckInputFile(path, kMaxPlyInputBytes, "a PLY point cloud");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open for reading");
  // The header first, so that counts the file cannot hold are refused before the body is read;
  // then the whole file in memory: its size bounds every allocation below.
  std::string data(static_cast<std::size_t>(std::min(file_size, kMaxHeaderBytes)), '\0');
  in.read(data.data(), static_cast<std::streamsize>(data.size()));
  if (static_cast<std::size_t>(in.gcount()) != data.size()) throw FileError(path, "read error");
  if (file_size > kMaxHeaderBytes && data.find("end_header") == std::string::npos)
    throw FileError(path, "no end_header in the first " + std::to_string(kMaxHeaderBytes) +
                              " bytes (not a PLY header)");

  const Header header = ParseHeader(data, path);
  const Element* vertex = nullptr;
  for (const Element& e : header.elements)
    if (e.name == "vertex") vertex = &e;
  if (!vertex) throw FileError(path, "no 'vertex' element in header");
  int xyz_index[3] = {-1, -1, -1};
  const char* axis[3] = {"x", "y", "z"};
  for (std::size_t i = 0; i < vertex->properties.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (vertex->properties[i].name == axis[k]) xyz_index[k] = static_cast<int>(i);
  for (int k = 0; k < 3; ++k) {
    if (xyz_index[k] < 0) throw FileError(path, std::string("vertex has no property '") + axis[k] + "'");
    const Property& p = vertex->properties[xyz_index[k]];
    if (p.is_list || !IsFloating(p.type))
      throw FileError(path, std::string("vertex property '") + axis[k] +
                                "' must be float or double");
  }

  const std::uint64_t body = file_size - header.body_offset;
  std::uint64_t needed = 0;
  for (const Element& e : header.elements) {
    const std::uint64_t per_item = MinBytesPerItem(e, header.encoding);
    if (per_item == 0) continue;
    if (e.count > (body - needed) / per_item)
      throw FileError(path, "header declares " + std::to_string(e.count) + " '" + e.name +
                                "' elements but only " + std::to_string(body) +
                                " bytes follow the header (truncated file?)");
    needed += e.count * per_item;
  }

  const std::size_t head = data.size();
  data.resize(static_cast<std::size_t>(file_size));
  in.read(data.data() + head, static_cast<std::streamsize>(file_size - head));
  if (static_cast<std::uint64_t>(in.gcount()) != file_size - head)
    throw FileError(path, "read error (file changed or unreadable while reading)");

  PointCloud cloud;
  cloud.points.resize(3, static_cast<Eigen::Index>(vertex->count));
  std::uint64_t non_finite = 0;
  std::size_t pos = header.body_offset;
  BinaryCursor bin(data, pos, header.encoding, path);
  TextCursor text(data, pos, path);
  const bool ascii = header.encoding == Encoding::kAscii;
  for (const Element& e : header.elements) {
    const bool is_vertex = &e == vertex;
    const std::string what_text = "element '" + e.name + "'";
    const char* what = what_text.c_str();
    if (e.properties.empty()) continue;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if ((i & 0xFFFF) == 0) CheckCancelled();  // a batch item's --timeout covers parsing too
      for (std::size_t j = 0; j < e.properties.size(); ++j) {
        const Property& p = e.properties[j];
        if (p.is_list) {
          const std::uint64_t n = ListCount(ascii ? text.Number(what) : bin.Read(p.count_type, what), path, what);
          if (ascii) {
            for (std::uint64_t m = 0; m < n; ++m) text.Next(what);
          } else {
            bin.Skip(n * SizeOf(p.type), what);
          }
          continue;
        }
        const double v = ascii ? text.Number(what) : bin.Read(p.type, what);
        if (!is_vertex) continue;
        for (int k = 0; k < 3; ++k)
          if (xyz_index[k] == static_cast<int>(j)) cloud.points(k, static_cast<Eigen::Index>(i)) = v;
      }
      if (is_vertex && !cloud.points.col(static_cast<Eigen::Index>(i)).allFinite()) ++non_finite;
    }
    if (is_vertex) break;  // later elements cannot change the vertices
  }
  if (non_finite > 0)
    throw FileError(path, std::to_string(non_finite) + " of " + std::to_string(vertex->count) +
                              " vertices have non-finite coordinates");
  return cloud;
}

void WritePly(const std::string& path, const PointCloud& cloud, bool binary) {
  // ReadPly refuses non-finite vertices, so writing them would produce an unreadable file.
  if (!cloud.points.allFinite())
    throw FileError(path, "cannot write point cloud: it holds non-finite coordinates");
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii")
        << " 1.0\ncomment written by cablefit\nelement vertex " << cloud.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
    for (int i = 0; i < cloud.size(); ++i) {
      if (!binary) {
        out << FormatDouble(cloud.points(0, i)) << ' ' << FormatDouble(cloud.points(1, i)) << ' '
            << FormatDouble(cloud.points(2, i)) << '\n';
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        unsigned char b[8];
        const double v = cloud.points(k, i);
        std::memcpy(b, &v, 8);
        if constexpr (std::endian::native != std::endian::little)
          for (int m = 0; m < 4; ++m) std::swap(b[m], b[7 - m]);
        out.write(reinterpret_cast<const char*>(b), 8);
      }
    }
  });
}

}  // namespace cablefit
