#include "cablefit/formats/file_digest.h"

#include <fstream>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "sha256.h"

namespace cablefit {

std::string FileSha256(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot be read to compute its SHA-256");
  internal::Sha256 sha;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize got = in.gcount();
    if (got > 0) sha.Update(buffer.data(), static_cast<std::size_t>(got));
  }
  if (in.bad()) throw FileError(path, "read error while computing its SHA-256");
  return sha.HexDigest();
}

}  // namespace cablefit
