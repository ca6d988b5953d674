#pragma once
// nmea_msgs/Sentence (one NMEA 0183 sentence with a header), as nmea_navsat_driver and most GNSS
// drivers publish raw receiver output. Debian packages no nmea_msgs, so the message is declared
// here with the ROS serialization traits genmsg would generate; the MD5 sum is the real one, so
// bags recorded with the real package read (and bags written with this one read elsewhere).
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <std_msgs/Header.h>

#include <boost/shared_ptr.hpp>

#include <string>

namespace nmea_msgs {

struct Sentence {
  std_msgs::Header header;
  std::string sentence;  ///< e.g. "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,,,,*47"

  using Ptr = boost::shared_ptr<Sentence>;
  using ConstPtr = boost::shared_ptr<const Sentence>;
};

}  // namespace nmea_msgs

namespace ros::message_traits {

template <>
struct IsMessage<nmea_msgs::Sentence> : TrueType {};
template <>
struct IsMessage<const nmea_msgs::Sentence> : TrueType {};
template <>
struct HasHeader<nmea_msgs::Sentence> : TrueType {};
template <>
struct HasHeader<const nmea_msgs::Sentence> : TrueType {};

template <>
struct MD5Sum<nmea_msgs::Sentence> {
  static const char* value() { return "9f221efc5f4b3bac7ce4af102b32308b"; }
  static const char* value(const nmea_msgs::Sentence&) { return value(); }
};

template <>
struct DataType<nmea_msgs::Sentence> {
  static const char* value() { return "nmea_msgs/Sentence"; }
  static const char* value(const nmea_msgs::Sentence&) { return value(); }
};

template <>
struct Definition<nmea_msgs::Sentence> {
  static const char* value() {
    static const std::string definition =
        "# A message representing a single NMEA0183 sentence.\n"
        "Header header\n"
        "string sentence\n"
        "\n"
        "================================================================================\n"
        "MSG: std_msgs/Header\n" +
        std::string(Definition<std_msgs::Header>::value());
    return definition.c_str();
  }
  static const char* value(const nmea_msgs::Sentence&) { return value(); }
};

}  // namespace ros::message_traits

namespace ros::serialization {

template <>
struct Serializer<nmea_msgs::Sentence> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    stream.next(m.sentence);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};

}  // namespace ros::serialization
