#include "cablefit/formats/kbl_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <string>

#include "cablefit/core/base/errors.h"
#include "test_support.h"

namespace cablefit {
namespace {

std::string Sample(const std::string& what) {
  const std::map<std::string, std::string> files = {
      {"gearbox", "kblxml_2.3sr-1_000971250_ltgs_getriebe_170718.kbl"},
      {"generator", "kblxml_2.3sr-1_000971230_ltgs_generator_170718.kbl"},
      {"movo", "kblxml_2.3sr-1_000971619_ltgs_movo_170718.kbl"},
      {"battery_plus", "kblxml_2.3sr-1_000971228_ltgs_batterie_plus_170718.kbl"},
      {"battery_minus", "kblxml_2.3sr-1_000971235_ltgs_batt._minus_170718.kbl"}};
  return (testing::SourceDir() / "tests/data/kbl" / files.at(what)).string();
}

const KblSegment& SegmentById(const KblHarness& h, const std::string& id) {
  const auto it = std::find_if(h.segments.begin(), h.segments.end(),
                               [&](const KblSegment& s) { return s.id == id; });
  if (it == h.segments.end()) throw std::runtime_error("no segment " + id);
  return *it;
}

// The measure of the B-spline reading: degree 6, 7 control points, knots 0..13, domain
// [6, 7]; the curve is 625.09 mm long, its Virtual_length, and ends on both nodes' own points.
TEST(KblFile, GearboxSegmentIsAsLongAsItsVirtualLengthAndEndsOnItsNodes) {
  const KblHarness h = ReadKblFile(Sample("gearbox"));
  ASSERT_EQ(h.segments.size(), 1u);
  ASSERT_EQ(h.drawing.cables.size(), 1u);
  const KblSegment& s = h.segments[0];
  EXPECT_EQ(h.drawing.cables[0].name, s.id);
  EXPECT_NEAR(s.drawn_length, 0.62509, 1e-5);
  ASSERT_TRUE(s.virtual_length.has_value());
  EXPECT_NEAR(*s.virtual_length, 0.62509, 5e-6);
  // Both nodes carry a Cartesian_point here, so this measures the curve against them.
  EXPECT_LT(s.node_miss, 1e-5);
  EXPECT_EQ(h.version, "2.3 SR-1");
  ASSERT_EQ(s.wires.size(), 1u);
  ASSERT_TRUE(s.wires[0].outside_diameter.has_value());
  EXPECT_GT(*s.wires[0].outside_diameter, 1e-4);
  EXPECT_LT(*s.wires[0].outside_diameter, 0.05);
  EXPECT_TRUE(h.drawing.junctions.empty());
}

TEST(KblFile, GeneratorHarnessHasThreeSegmentsMeetingAtOneNode) {
  const KblHarness h = ReadKblFile(Sample("generator"));
  ASSERT_EQ(h.segments.size(), 3u);
  // Node_2 joins all three: one breakout with an end of each.
  ASSERT_EQ(h.drawing.junctions.size(), 1u);
  const CableJunction& j = h.drawing.junctions[0];
  ASSERT_EQ(j.ends.size(), 3u);
  std::set<std::string> at_junction;
  for (const CableJunction::End& e : j.ends) {
    const KblSegment& s = h.segments[static_cast<size_t>(e.cable)];
    EXPECT_EQ(e.at_start ? s.start.node : s.end.node, "Node_2");
    at_junction.insert(s.id);
  }
  EXPECT_EQ(at_junction, (std::set<std::string>{"Segment_1", "Segment_2", "Segment_3"}));
  const KblSegment& s1 = SegmentById(h, "Segment_1");
  ASSERT_EQ(s1.fixings.size(), 1u);
  EXPECT_EQ(s1.fixings[0].id, "Fixing_occurrence_1");
  EXPECT_NEAR(s1.fixings[0].location, 0.886766, 1e-9);
  EXPECT_EQ(s1.fixings[0].type, "SPT");
  ASSERT_EQ(s1.protections.size(), 1u);
  EXPECT_EQ(s1.protections[0].type, "TAPE");
  EXPECT_NEAR(s1.protections[0].start, 0.045496, 1e-12);
  EXPECT_NEAR(s1.protections[0].linear_density.value(), 0.006, 1e-15);
  // Connection -> wire occurrence -> General_wire: 1.6, 1.6 and 5.1 mm wires in Segment_1.
  ASSERT_EQ(s1.wires.size(), 3u);
  std::multiset<double> diameters;
  for (const KblWire& w : s1.wires)
    diameters.insert(std::round(1e4 * w.outside_diameter.value()) / 10);
  EXPECT_EQ(diameters, (std::multiset<double>{1.6, 1.6, 5.1}));
  for (const KblWire& w : s1.wires) EXPECT_TRUE(w.linear_density.has_value());
  EXPECT_EQ(SegmentById(h, "Segment_2").wires.size(), 1u);
  EXPECT_EQ(SegmentById(h, "Segment_3").wires.size(), 2u);
  // Units: the wire's mass is in GramPerMetre, its bend radius in milli metre.
  const auto thick = std::find_if(s1.wires.begin(), s1.wires.end(), [](const KblWire& w) {
    return w.outside_diameter.value() > 0.005;
  });
  EXPECT_NEAR(thick->linear_density.value(), 0.068, 1e-12);
  EXPECT_NEAR(thick->min_bend_radius.value(), 0.0153, 1e-12);
  EXPECT_NEAR(thick->conductor_area.value(), 6e-6, 1e-15);
  EXPECT_NEAR(s1.cross_section_area.value(), 63.617251e-6, 1e-12);
  EXPECT_EQ(s1.start.connectors, std::vector<std::string>{"TMM.2A1"});
  EXPECT_EQ(s1.end.segments_at_node, 3);
  // No segment's curve misses its node: ends at the junction agree to 10 um.
  for (const KblSegment& s : h.segments) EXPECT_LT(s.node_miss, 1e-5) << s.id;
  for (const KblSegment& s : h.segments) {
    EXPECT_NEAR(s.drawn_length, s.virtual_length.value(), 1e-4) << s.id;
  }
}

TEST(KblFile, MovoHarnessReadsThirtySegmentsAndAllCurvesLand) {
  const KblHarness h = ReadKblFile(Sample("movo"));
  EXPECT_EQ(h.segments.size(), 30u);
  EXPECT_TRUE(h.drawing.skipped.empty()) << h.drawing.skipped.front();
  std::set<std::string> nodes;
  for (const KblSegment& s : h.segments) {
    nodes.insert(s.start.node);
    nodes.insert(s.end.node);
    EXPECT_LT(s.node_miss, 1e-5) << s.id;
  }
  // Segment_6's curve runs on through its End_node Node_7 to Node_8 (over Segment_18): it is
  // cut at Node_7 and is then as long as its Virtual_length; every other curve lands as read.
  ASSERT_EQ(h.notes.size(), 1u);
  EXPECT_NE(h.notes[0].find("Segment_6: centre curve runs 50.00 mm past its End_node Node_7"),
            std::string::npos)
      << h.notes[0];
  const KblSegment& s6 = SegmentById(h, "Segment_6");
  EXPECT_NEAR(s6.drawn_length, s6.virtual_length.value(), 1e-4);
  for (const KblSegment& s : h.segments) {
    EXPECT_NEAR(s.drawn_length, s.virtual_length.value(), 1e-5) << s.id;
  }
  EXPECT_EQ(nodes.size(), 31u);
  // A tree of 30 segments over 31 nodes: every node of two or more segments is a junction.
  int inner = 0;
  for (const CableJunction& j : h.drawing.junctions) inner += j.ends.size() >= 2;
  EXPECT_GT(inner, 0);
  size_t ends_joined = 0;
  for (const CableJunction& j : h.drawing.junctions) ends_joined += j.ends.size();
  EXPECT_EQ(ends_joined + (31 - h.drawing.junctions.size()), 60u);
}

TEST(KblFile, BatteryCablesAreOneSegmentEach) {
  for (const char* which : {"battery_plus", "battery_minus"}) {
    const KblHarness h = ReadKblFile(Sample(which));
    ASSERT_EQ(h.segments.size(), 1u) << which;
    EXPECT_NEAR(h.segments[0].drawn_length, h.segments[0].virtual_length.value(),
                0.01 * h.segments[0].virtual_length.value())
        << which;
  }
}

// Malformed files: one line naming the element.
class KblBadInput : public ::testing::Test {
 protected:
  std::string Write(const std::string& text) {
    const auto dir = testing::FreshTempDir("kbl_bad");
    const std::string path = (dir / "bad.kbl").string();
    std::ofstream(path) << text;
    return path;
  }
  // The gearbox sample with `from` replaced by `to` (first occurrence).
  std::string Edited(const std::string& from, const std::string& to) {
    std::string text = testing::ReadTextFile(Sample("gearbox"));
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return Write(text);
  }
};

TEST_F(KblBadInput, NotXml) {
  EXPECT_THROW_WITH(ReadKblFile(Write("this is not <xml")), FileError, "not XML");
}

TEST_F(KblBadInput, WrongRoot) {
  EXPECT_THROW_WITH(ReadKblFile(Write("<?xml version=\"1.0\"?><Harness/>")), FileError,
                    "not a KBL_container");
}

TEST_F(KblBadInput, OtherNamespaceVersion) {
  EXPECT_THROW_WITH(ReadKblFile(Edited("KBL2.3/KBLSchema", "KBL3.0/KBLSchema")), FileError,
                    "only KBL 2.x");
}

TEST_F(KblBadInput, DanglingControlPoint) {
  EXPECT_THROW_WITH(ReadKblFile(Edited("<Control_points>Cartesian_point_",
                                       "<Control_points>Nowhere_1 Cartesian_point_")),
                    FileError, "reference 'Nowhere_1' names no element");
}

TEST_F(KblBadInput, DanglingRoutedSegment) {
  EXPECT_THROW_WITH(
      ReadKblFile(Edited("<Segments>Segment_1</Segments>", "<Segments>Segment_9</Segments>")),
      FileError, "'Segment_9' names no Segment");
}

TEST_F(KblBadInput, WireThroughUnconnectedSegmentsIsANote) {
  // Generator: Routing id_338_0 runs Segment_1 (Node_1-Node_2) and Segment_2 (Node_3-Node_2);
  // rerouted through Segment_1 and a segment moved off Node_2, it has a gap.
  std::string text = testing::ReadTextFile(Sample("generator"));
  const size_t seg2 = text.find("<Segment id=\"Segment_2\">");
  const size_t end_node = text.find("<End_node>Node_2</End_node>", seg2);
  ASSERT_NE(end_node, std::string::npos);
  text.replace(end_node, std::string("<End_node>Node_2</End_node>").size(),
               "<End_node>Node_4</End_node>");
  const KblHarness h = ReadKblFile(Write(text), {.node_tolerance = 1.0});
  bool noted = false;
  for (const std::string& n : h.notes)
    noted = noted || n.find("Routing id_338_0: its segments are not connected (Segment_2") !=
                         std::string::npos;
  EXPECT_TRUE(noted);
  const KblHarness ok = ReadKblFile(Sample("generator"));
  for (const std::string& n : ok.notes) EXPECT_EQ(n.find("not connected"), std::string::npos) << n;
}

TEST_F(KblBadInput, ProtectionAreaOutsideTheSegment) {
  std::string text = testing::ReadTextFile(Sample("generator"));
  const size_t at = text.find("<End_location>1.000000</End_location>");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("<End_location>1.000000</End_location>").size(),
               "<End_location>1.5</End_location>");
  EXPECT_THROW_WITH(ReadKblFile(Write(text)), FileError,
                    "Protection_area Protection_area_1 of Segment Segment_1: Start_location");
}

TEST_F(KblBadInput, MissingUnit) {
  EXPECT_THROW_WITH(ReadKblFile(Edited("<Si_unit_name>metre</Si_unit_name>", "")), FileError,
                    "Unit ");
}

TEST_F(KblBadInput, LengthInAMassUnit) {
  const std::string text = testing::ReadTextFile(Sample("gearbox"));
  // Point the segment's Virtual_length at the file's gram unit.
  const size_t vl = text.find("<Virtual_length");
  ASSERT_NE(vl, std::string::npos);
  const size_t uc = text.find("<Unit_component>", vl);
  const size_t uc_end = text.find("</Unit_component>", uc);
  const size_t gram = text.rfind("<Unit id=\"", text.find("<Si_unit_name>gram</Si_unit_name>"));
  ASSERT_NE(gram, std::string::npos);
  const size_t q = gram + std::string("<Unit id=\"").size();
  const std::string gram_id = text.substr(q, text.find('"', q) - q);
  std::string edited = text;
  edited.replace(uc, uc_end - uc, "<Unit_component>" + gram_id);
  EXPECT_THROW_WITH(ReadKblFile(Write(edited)), FileError, "is a mass, expected a length");
}

TEST_F(KblBadInput, ANodeOffItsOnlyCurveIsPlacedAtTheCurveEnd) {
  // Move the end node's own point 50 mm: its only segment's curve decides where it is.
  const std::string text = testing::ReadTextFile(Sample("gearbox"));
  const size_t node = text.find("<Node id=\"Node_2\"");
  ASSERT_NE(node, std::string::npos);
  const size_t cp = text.find("<Cartesian_point>", node) + std::string("<Cartesian_point>").size();
  const std::string cp_id = text.substr(cp, text.find('<', cp) - cp);
  std::string edited = text;
  const size_t def = edited.find("<Cartesian_point id=\"" + cp_id + "\">");
  const size_t c0 = edited.find("<Coordinates>", def) + std::string("<Coordinates>").size();
  const size_t c1 = edited.find("</Coordinates>", c0);
  const double x = std::stod(edited.substr(c0, c1 - c0));
  edited.replace(c0, c1 - c0, std::to_string(x + 50.0));
  const KblHarness h = ReadKblFile(Write(edited));
  ASSERT_EQ(h.segments.size(), 1u);
  EXPECT_TRUE(h.drawing.skipped.empty());
  ASSERT_EQ(h.notes.size(), 1u);
  EXPECT_NE(h.notes[0].find("Node Node_2: its Cartesian_point is 50.00 mm from where its only "
                            "segment's centre curve ends: placed there"),
            std::string::npos)
      << h.notes[0];
  // The curve is the file's, untouched: as long as its Virtual_length.
  const KblSegment& s = h.segments[0];
  EXPECT_FALSE(s.end_drawn_to_node);
  EXPECT_NEAR(s.drawn_length, s.virtual_length.value(), 1e-5);
}

// tests/data/kbl/inconsistent_nodes_4.kbl: Node_1 -S1- Node_2 -S2- Node_3, and S3, S4 from
// Node_3 (a breakout). Node_3's own point is 25 mm off where the curves of S2, S3, S4 meet,
// S4's curve starts 30 mm short of that, Node_1's point is 40 mm off S1's start.
TEST(KblFile, InconsistentNodesAreBuiltFromWhereTheCurvesMeetWithOneNoteEach) {
  const KblHarness h = ReadKblFile(
      (testing::SourceDir() / "tests/data/kbl/inconsistent_nodes_4.kbl").string());
  ASSERT_EQ(h.segments.size(), 4u);
  EXPECT_TRUE(h.drawing.skipped.empty());
  auto noted = [&](const std::string& text) {
    return std::count_if(h.notes.begin(), h.notes.end(), [&](const std::string& n) {
      return n.find(text) != std::string::npos;
    });
  };
  EXPECT_EQ(noted("Node Node_1: its Cartesian_point is 40.00 mm from where its only segment's "
                  "centre curve ends: placed there"), 1);
  EXPECT_EQ(noted("Node Node_3: its Cartesian_point is 25.00 mm from where its segments' centre "
                  "curves meet: placed there"), 1);
  EXPECT_EQ(noted("Segment Segment_4: centre curve ends 30.00 mm from its Start_node Node_3: its "
                  "end drawn onto the node"), 1);
  EXPECT_EQ(noted("Node "), 2);
  EXPECT_EQ(noted("trimmed"), 0);
  // Node_3 is one breakout of three ends, where the curves meet.
  const Vec3 meet(0.340, 0.180, 0.010);
  int breakouts = 0;
  for (const CableJunction& j : h.drawing.junctions) {
    if (j.ends.size() != 3) continue;
    ++breakouts;
    EXPECT_LT((j.position - meet).norm(), 1e-9);
    for (const CableJunction::End& e : j.ends) {
      const Polyline& c = h.drawing.cables[static_cast<size_t>(e.cable)].centreline;
      EXPECT_LT((c.points.col(e.at_start ? 0 : c.size() - 1) - meet).norm(), 1e-9)
          << h.segments[static_cast<size_t>(e.cable)].id;
    }
  }
  EXPECT_EQ(breakouts, 1);
  // The curves that reach their nodes keep the file's shape and length; S4 says it was drawn.
  for (const char* id : {"Segment_1", "Segment_2", "Segment_3"}) {
    const KblSegment& s = SegmentById(h, id);
    EXPECT_FALSE(s.end_drawn_to_node) << id;
    EXPECT_NEAR(s.drawn_length, s.virtual_length.value(), 1e-5) << id;
  }
  const KblSegment& s4 = SegmentById(h, "Segment_4");
  EXPECT_TRUE(s4.end_drawn_to_node);
  EXPECT_NEAR(s4.node_miss, 0.030, 1e-9);
  // Its other end stayed on Node_5.
  const Polyline& c4 = h.drawing.cables[static_cast<size_t>(
      std::find_if(h.segments.begin(), h.segments.end(),
                   [](const KblSegment& s) { return s.id == "Segment_4"; }) -
      h.segments.begin())].centreline;
  EXPECT_LT((c4.points.col(c4.size() - 1) - Vec3(0.220, 0.330, -0.030)).norm(), 1e-9);
}

}  // namespace
}  // namespace cablefit
