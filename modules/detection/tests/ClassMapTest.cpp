// The class map: defaults (person non-rigid, car rigid), COCO names or ids, dropped classes and
// errors that name the bad entry.
#include <dynslam/detection/ClassMap.h>
#include <dynslam/detection/CocoClasses.h>

#include <gtest/gtest.h>

namespace det = dynslam::detection;
using dynslam::core::MotionModel;

TEST(CocoClasses, NamesAndIdsMatchTheYoloNumbering) {
  EXPECT_EQ(det::cocoClassName(0), "person");
  EXPECT_EQ(det::cocoClassName(2), "car");
  EXPECT_EQ(det::cocoClassName(79), "toothbrush");
  EXPECT_EQ(det::cocoClassId("truck"), 7);
  EXPECT_EQ(det::cocoClassId("traffic_light"), 9);
  EXPECT_FALSE(det::cocoClassId("pedestrian"));
  EXPECT_THROW(det::cocoClassName(80), std::out_of_range);
}

TEST(ClassMap, DefaultKeepsPersonNonRigidAndCarRigidOnly) {
  const det::ClassMap map;
  ASSERT_TRUE(map.lookup(0));
  EXPECT_EQ(map.lookup(0)->category, "person");
  EXPECT_EQ(map.lookup(0)->model, MotionModel::NonRigid);
  ASSERT_TRUE(map.lookup(2));
  EXPECT_EQ(map.lookup(2)->category, "car");
  EXPECT_EQ(map.lookup(2)->model, MotionModel::Rigid);
  EXPECT_FALSE(map.lookup(5));  // bus: dropped
  EXPECT_EQ(map.toString(), "person:person:non_rigid car:car:rigid");
}

TEST(ClassMap, ParsesNamesIdsAndSeparatorsAndRoundTrips) {
  const auto map = det::ClassMap::parse(
      "person:person:non_rigid, car:car:rigid bus:car:rigid  7:car:rigid\tbicycle:other:rigid");
  EXPECT_EQ(map.lookup(5)->category, "car");
  EXPECT_EQ(map.lookup(7)->model, MotionModel::Rigid);  // truck by id
  EXPECT_EQ(map.lookup(1)->category, "other");
  EXPECT_FALSE(map.lookup(3));  // motorcycle not listed: dropped
  const auto again = det::ClassMap::parse(map.toString());
  EXPECT_EQ(again.toString(), map.toString());
}

TEST(ClassMap, ErrorsNameTheEntry) {
  const auto errorOf = [](const std::string& spec) -> std::string {
    try {
      det::ClassMap::parse(spec);
    } catch (const det::ClassMapError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(errorOf("person:person").find("'person:person': expected"), std::string::npos);
  EXPECT_NE(errorOf("pedestrian:person:non_rigid").find("'pedestrian' is neither"),
            std::string::npos);
  EXPECT_NE(errorOf("80:person:rigid").find("'80' is neither"), std::string::npos);
  EXPECT_NE(errorOf("bus:vehicle:rigid").find("category 'vehicle'"), std::string::npos);
  EXPECT_NE(errorOf("bus:car:solid").find("motion 'solid'"), std::string::npos);
  EXPECT_NE(errorOf("car:car:rigid 2:car:rigid").find("mapped twice"), std::string::npos);
  EXPECT_NE(errorOf(" ").find("no entries"), std::string::npos);
}
