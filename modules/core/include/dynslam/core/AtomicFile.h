#pragma once
// Files written whole or not at all. A crash, a kill -9 or a full disk part-way through a write
// leaves the file as it was before (or absent), never a half-written summary.json or CSV that the
// next program (dynslam-sweep's resume, a plotting script) would take for a complete one.
#include <functional>
#include <sstream>
#include <string>

namespace dynslam::core {

/// Writes `content` to a temporary file beside `path` (".<name>.<pid>.tmp" in the same folder),
/// syncs it and renames it onto `path`; rename within one folder is atomic on POSIX file
/// systems. Throws std::runtime_error naming `path` when any step fails (the temporary removed).
void writeFileAtomically(const std::string& path, const std::string& content);

/// For files a library writes from a path (MRPT's map.3Dscene): `write` is called with the
/// temporary's path, which is then synced and renamed onto `path` as above.
void replaceFileAtomically(const std::string& path,
                           const std::function<void(const std::string& temporary)>& write);

/// Text collected in memory and written by commit() through writeFileAtomically. A file that is
/// never committed (an exception on the way) is never created.
class AtomicTextFile {
 public:
  explicit AtomicTextFile(std::string path) : path_(std::move(path)) {}

  std::ostream& stream() { return text_; }
  const std::string& path() const { return path_; }
  void commit() { writeFileAtomically(path_, text_.str()); }

 private:
  std::string path_;
  std::ostringstream text_;
};

}  // namespace dynslam::core
