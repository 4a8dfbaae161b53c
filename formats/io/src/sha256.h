// SHA-256 (FIPS 180-4, "Secure Hash Standard", sec. 6.2) of a byte stream. The provenance of
// every output hashes its inputs; OpenSSL's libcrypto did that in ~3 ms of start-up per process
// (loading the library and its providers), more than `cablefit simulate` needs for its solve.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace cablefit::internal {

class Sha256 {
 public:
  Sha256();
  void Update(const void* data, std::size_t size);
  /// The digest as lower-case hex; the object is spent afterwards.
  std::string HexDigest();

 private:
  void Block(const std::uint8_t* block);  // one 64-byte block into state_

  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

}  // namespace cablefit::internal
