#include "core/base/files.h"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "core/base/errors.h"

namespace shadelab {
namespace fs = std::filesystem;

fs::path temporaryBeside(const fs::path& target) {
  // Built by appending: GCC 12 misreports "." + std::string&& under -O2 (-Wrestrict).
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += target.extension().string();
  return target.parent_path() / name;
}

void replaceWith(const fs::path& temporary, const fs::path& target) {
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw InputError("cannot write '" + target.string() + "': " + error.message());
  }
}

void checkWritableFolder(const fs::path& path) {
  if (path.empty()) throw InputError("output path is empty");
  fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(parent, error))
    throw InputError("output '" + path.string() + "': folder '" + parent.string() +
                     "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0)
    throw InputError("output '" + path.string() + "': folder '" + parent.string() +
                     "' is not writable");
  if (fs::is_directory(path, error))
    throw InputError("output '" + path.string() + "' is a folder, expected a file name");
}

void writeTextFile(const fs::path& path, const std::string& text) {
  checkWritableFolder(path);
  fs::path temporary = temporaryBeside(path);
  {
    std::ofstream file(temporary, std::ios::binary);
    file << text;
    if (!file.flush()) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw InputError("cannot write '" + path.string() + "'");
    }
  }
  replaceWith(temporary, path);
}

}  // namespace shadelab
