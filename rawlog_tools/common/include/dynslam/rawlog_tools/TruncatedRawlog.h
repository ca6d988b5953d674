#pragma once
// Fixtures for tests of rawlog readers: copies of a good rawlog that end early, the way a
// recorder that crashed or a full disk leaves them. Example (in a test):
//
//   sevenscenes2rawlog --in ../shared/data/7scenes --out good.rawlog --last 9
//   writeRawlogCutInsideObservation("good.rawlog", "cut.rawlog", 5);
//     -> valid gzip; 5 complete observations, then the first half of the 6th one's bytes.
//   writeRawlogCutRawBytes("good.rawlog", "crash.rawlog", 0.5);
//     -> the first half of good.rawlog's compressed bytes: the gzip stream itself ends early.
//
// A reader should yield the complete observations and then report the truncation.
#include <cstddef>
#include <string>

namespace dynslam::rawlog_tools {

/// Returns the number of uncompressed bytes written. Throws ConversionError when the source
/// holds fewer than completeObservations + 1 observations or cannot be read.
size_t writeRawlogCutInsideObservation(const std::string& source, const std::string& target,
                                       size_t completeObservations);

/// Copies the first `fraction` (0 < fraction < 1) of the source file's bytes. Returns the
/// number of bytes written.
size_t writeRawlogCutRawBytes(const std::string& source, const std::string& target,
                              double fraction);

}  // namespace dynslam::rawlog_tools
