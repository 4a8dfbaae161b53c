#include "cablefit/formats/file_digest.h"

#include <gtest/gtest.h>

#include <string>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

std::string Write(const std::string& name, const std::string& bytes) {
  return testing::WriteTempFile("file_digest", name, bytes);
}

// The FIPS 180-2 test vectors: the empty message, "abc", 56 bytes (its padding needs a second
// block), and one longer than a read buffer.
TEST(FileDigest, Sha256OfKnownMessages) {
  EXPECT_EQ(FileSha256(Write("empty", "")),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(FileSha256(Write("abc", "abc")),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(FileSha256(Write("two_blocks", "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq")),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(FileSha256(Write("million", std::string(1000000, 'a'))),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(FileDigest, AMissingFileIsAFileError) {
  EXPECT_THROW(FileSha256("/nonexistent/cablefit/file.step"), FileError);
}

}  // namespace
}  // namespace cablefit
