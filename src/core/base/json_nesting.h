#pragma once
// A limit on how deeply JSON text nests arrays and objects, checked before
// a parser sees it. tinygltf copies a file's JSON into its own values by
// recursion, one call per level: a glTF nested 200,000 deep in "extras"
// overflowed the stack (SIGSEGV). Scene files get the same limit, so no
// recursive walk of them (dump(), a future reader) can either. Real scenes
// and glTF files nest fewer than 20 levels.
#include <cstddef>
#include <string>
#include <string_view>

namespace shadelab {

inline constexpr size_t kMaxJsonNesting = 256;

// Throws InputError "SOURCE: JSON nests deeper than N levels (at line L)"
// when `text` opens more than `limit` arrays/objects at once (brackets inside
// strings do not count). Says nothing about whether the text is valid JSON.
void checkJsonNesting(std::string_view text, const std::string& source,
                      size_t limit = kMaxJsonNesting);

}  // namespace shadelab
