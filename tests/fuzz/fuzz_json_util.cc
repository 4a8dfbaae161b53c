// libFuzzer target: the JSON layer every JSON reader stands on — ReadJsonFile, then every
// FieldReader accessor on every field of the root object, and the write path back.
#include "cablefit/formats/json_util.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using cablefit::json::FieldReader;
  using cablefit::json::Json;
  const std::string path = cablefit::fuzz::WriteScratch("input.json", data, size);
  Json doc;
  bool parsed = false;
  cablefit::fuzz::ExpectOnlyInputErrors("ReadJsonFile", [&] {
    doc = cablefit::json::ReadJsonFile(path);
    parsed = true;
  });
  if (!parsed || !doc.is_object()) return 0;
  const FieldReader r(doc, path, "root");
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string key = it.key();
    (void)cablefit::json::Describe(it.value());
    auto each = [&](auto&& f) { cablefit::fuzz::ExpectOnlyInputErrors("FieldReader", f); };
    each([&] { (void)r.RequireObject(key); });
    each([&] { (void)r.RequireArray(key); });
    each([&] { (void)r.RequireString(key); });
    each([&] { (void)r.RequireNumber(key); });
    each([&] { (void)r.RequirePositive(key); });
    each([&] { (void)r.RequireNonNegative(key); });
    each([&] { (void)r.OptionalNumber(key, 0.0); });
    each([&] { (void)r.RequireVec3(key); });
    each([&] { (void)r.Child(key).Has("x"); });
  }
  cablefit::fuzz::ExpectOnlyInputErrors("RequireKnownKeys", [&] {
    cablefit::json::RequireKnownKeys(r, {"format", "name"});
  });
  // What was read must be writable again (valid UTF-8 is checked by the parser).
  cablefit::fuzz::ExpectOnlyInputErrors("WriteJsonFile", [&] {
    cablefit::json::WriteJsonFile(
        (cablefit::fuzz::ScratchDir() / "output.json").string(), doc, -1);
  });
  return 0;
}
