#pragma once
// Converts one ROS 1 bag into an observations-only rawlog: reads the bag once in recording
// order (rosbag::View over the mapped topics), turns messages into observations as the topic
// map says, and writes them sorted by header stamp.
#include "TopicMap.h"

#include <dynslam/rawlog_tools/ColourImageStore.h>

#include <cstdio>
#include <map>
#include <string>

namespace dynslam::rawlog_tools {
class RawlogWriter;
}

namespace dynslam::rawlog_tools::bag {

struct ConversionSummary {
  size_t messages = 0;         ///< bag messages read on the mapped topics
  size_t unmatchedColour = 0;  ///< colour images without a depth image within rgbd_max_dt
  size_t unmatchedDepth = 0;
  size_t droppedGyro = 0;     ///< gyro samples outside the accelerometer's time span
  size_t outOfOrderImu = 0;   ///< accel/gyro samples whose stamp did not increase
  size_t gnssWithoutFix = 0;  ///< NavSatFix with status NO_FIX or non-finite coordinates
  size_t nmeaSkipped = 0;     ///< NMEA sentences MRPT's parser does not recognise
  size_t late = 0;            ///< observations beyond the reorder window (not written)
};

/// Throws ConversionError for a missing or unreadable bag, a mapped topic the bag does not have
/// (the message lists the bag's topics and types), a topic whose type does not fit its role,
/// or a message that cannot be read. `progress` (stderr) gets "messages done / total" lines.
ConversionSummary convertBag(const std::string& bagPath, const TopicMap& topics,
                             const std::string& topicsSource, ColourImageStore& images,
                             RawlogWriter& writer, std::FILE* progress);

}  // namespace dynslam::rawlog_tools::bag
