#pragma once
// Atomic output: write to a temporary file beside the target, then rename,
// so a failed or interrupted write never leaves a partial file.
#include <filesystem>
#include <string>

namespace shadelab {

// Same folder (rename is atomic there) and same extension (writers that pick
// the format by extension still work): "dir/.name.tmp-<pid>.ext".
std::filesystem::path temporaryBeside(const std::filesystem::path& target);
// Renames temporary to target; on failure removes the temporary and throws
// InputError naming the target.
void replaceWith(const std::filesystem::path& temporary, const std::filesystem::path& target);
// Throws InputError unless the folder of `path` exists and is writable.
void checkWritableFolder(const std::filesystem::path& path);
void writeTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace shadelab
