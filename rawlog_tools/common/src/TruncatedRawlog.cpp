#include "dynslam/rawlog_tools/TruncatedRawlog.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace dynslam::rawlog_tools {

size_t writeRawlogCutInsideObservation(const std::string& source, const std::string& target,
                                       size_t completeObservations) {
  mrpt::io::CFileGZInputStream inFile;
  if (!inFile.open(source)) throw ConversionError("cannot open rawlog " + source);
  auto in = mrpt::serialization::archiveFrom(inFile);
  mrpt::io::CFileGZOutputStream outFile;
  if (!outFile.open(target)) throw ConversionError("cannot create " + target);

  size_t bytesWritten = 0;
  // Objects are copied generically (whatever their class) by re-serializing each one into
  // memory, so the cut lands at a known place inside the (completeObservations+1)-th object.
  for (size_t i = 0; i <= completeObservations; ++i) {
    mrpt::serialization::CSerializable::Ptr object;
    try {
      object = in.ReadObject();
    } catch (const std::exception&) {
      throw ConversionError(source + " holds only " + std::to_string(i) + " objects; need " +
                            std::to_string(completeObservations + 1));
    }
    mrpt::io::CMemoryStream buffer;
    auto bufferArchive = mrpt::serialization::archiveFrom(buffer);
    bufferArchive << *object;
    const size_t size = static_cast<size_t>(buffer.getTotalBytesCount());
    const size_t keep = (i < completeObservations) ? size : size / 2;
    if (outFile.Write(buffer.getRawBufferData(), keep) != keep)
      throw ConversionError("write error on " + target);
    bytesWritten += keep;
  }
  outFile.close();
  return bytesWritten;
}

size_t writeRawlogCutRawBytes(const std::string& source, const std::string& target,
                              double fraction) {
  if (!(fraction > 0.0 && fraction < 1.0))
    throw ConversionError("truncation fraction must be in (0, 1)");
  std::ifstream in(source, std::ios::binary);
  if (!in) throw ConversionError("cannot open " + source);
  const auto size = std::filesystem::file_size(source);
  std::vector<char> bytes(static_cast<size_t>(static_cast<double>(size) * fraction));
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  std::ofstream out(target, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw ConversionError("cannot write " + target);
  return bytes.size();
}

}  // namespace dynslam::rawlog_tools
