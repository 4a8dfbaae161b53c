// Sweeping a tube along centrelines that made OCCT 7.6 fail or crash. The regression: the
// skeleton of the first tube in samples/harness/bent_tubes.stl (a straight run, a 90-degree bend
// of ~60 mm radius, a straight run; sub-micrometre noise off its plane), as the relax writer
// resampled it. BRepOffsetAPI_MakePipe with a disc died on it with a null read in
// BRepFill_Pipe::MakeShape (its corrected-Frenet sweep fails and the empty face table is used).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/cad_file.h"
#include "curve_distance.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::MaxDistanceToPolyline;

// 3 x 69 [m], about 4.9 mm apart.
constexpr double kBentSkeleton[][3] = {
    {0.0, -1.3825766560708433e-19, 5.849362775684336e-20},
    {0.004914694399924828, 9.976701831624987e-09, -9.260632689700635e-09},
    {0.009829388799858813, 1.7073045474725926e-08, -1.5778405382269e-08},
    {0.014744083199799059, 2.130251228994578e-08, -1.9589740874473998e-08},
    {0.019658777599742085, 2.3078724446091032e-08, -2.1117558408537357e-08},
    {0.024573471999685653, 2.2735147046151178e-08, -2.0696918017647045e-08},
    {0.029488166399628393, 2.0605539183762542e-08, -1.8661592775014518e-08},
    {0.034402860799569626, 1.702839179392462e-08, -1.534204109359488e-08},
    {0.0393175551995092, 1.234489799656546e-08, -1.1064051924812863e-08},
    {0.04423224959944739, 6.8980147812212735e-09, -6.150315051520564e-09},
    {0.049146943999384775, 1.0337541340409374e-09, -9.181744769905712e-10},
    {0.054061638399322084, -4.900388114363118e-09, 4.320233381051181e-09},
    {0.058976332799260026, -1.0555832925914126e-08, 9.258312838154241e-09},
    {0.0638910271991992, -1.558337256872336e-08, 1.3595336413156786e-08},
    {0.06880572159913997, -1.9632207644810548e-08, 1.70362050302009e-08},
    {0.07372041599908237, -2.2352570032218007e-08, 1.929228292514522e-08},
    {0.07863511039902576, -2.3396087543576837e-08, 2.008414584900021e-08},
    {0.08354980479896915, -2.241592197772275e-08, 1.9144170672957595e-08},
    {0.08846449919891182, -1.897459494310635e-08, 1.619713509450661e-08},
    {0.09337919359882012, -3.446948840301092e-08, 1.0728627197663881e-08},
    {0.09829394488932264, -7.742035926803166e-07, -1.2544299880906686e-08},
    {0.10320638728520894, 0.00012801780900414754, -6.27957377768968e-08},
    {0.10809626423349888, 0.000593113019009876, 2.5788288692136123e-08},
    {0.11293188317886929, 0.0014579276876573637, -3.562555831668182e-08},
    {0.1176809331067794, 0.00271448500829495, 2.827388724980109e-08},
    {0.12231167345081531, 0.004354356223793564, -5.4056811084044106e-08},
    {0.12679315109199066, 0.0063665874207496, 6.773665456763808e-08},
    {0.131095323916209, 0.008737868391480955, -3.993123153359579e-08},
    {0.13518963107098347, 0.011452014328563635, 1.9318333517421406e-08},
    {0.13904800531975126, 0.014491950426749264, -4.870398007336865e-09},
    {0.1426382090637695, 0.017844484119949426, -2.8576139699446097e-08},
    {0.1459433439608573, 0.021478652308700524, -9.293847713120465e-10},
    {0.1489409107578354, 0.025370610923588697, 2.2095399985348552e-08},
    {0.15161112510713437, 0.02949413051390756, -7.592631046357115e-10},
    {0.15393558142771727, 0.033822003469331584, -3.2431441813004463e-08},
    {0.15589927450963498, 0.03832494894355143, 1.5961202070648885e-09},
    {0.1574889336252266, 0.04297296039473497, 5.583857425725932e-08},
    {0.15869387186007816, 0.047734974173672735, -1.4567283608667352e-08},
    {0.15950358581812732, 0.05257939657385442, 2.4835333127735825e-08},
    {0.15990789950971088, 0.05747496889716486, -4.132408934523249e-08},
    {0.16000331235379273, 0.06238850660872823, -4.495212304364859e-08},
    {0.159999978577449, 0.0673032512024821, -4.3431629355342754e-08},
    {0.15999994972755574, 0.07221794560229415, -6.310119915702576e-08},
    {0.15999993766795614, 0.07713264000220028, -7.802490018996189e-08},
    {0.1599999299827207, 0.08204733440212816, -8.75858147010897e-08},
    {0.1599999262029662, 0.08696202880206776, -9.2272738604665e-08},
    {0.15999992594264037, 0.09187672320201111, -9.256797032641406e-08},
    {0.15999992881314434, 0.09679141760195238, -8.895666022885908e-08},
    {0.15999993442300592, 0.10170611200188763, -8.192820777805583e-08},
    {0.1599999423775798, 0.10662080640181466, -7.197587918443358e-08},
    {0.15999995228026287, 0.11153550080173272, -5.959632869711749e-08},
    {0.1599999637307595, 0.11645019520164221, -4.528929229964494e-08},
    {0.15999997632593013, 0.12136488960154454, -2.9557740346213377e-08},
    {0.1599999896612749, 0.12627958400144193, -1.2906852931185816e-08},
    {0.16000000333003767, 0.1311942784013369, 4.15604518585602e-09},
    {0.16000001692386057, 0.13610897280123255, 2.112173384514435e-08},
    {0.1600000300331338, 0.14102366720113146, 3.747957743273543e-08},
    {0.16000004224705164, 0.14593836160103638, 5.2717861984565443e-08},
    {0.1600000531537661, 0.15085305600094903, 6.63244333455912e-08},
    {0.16000006234262767, 0.15576775040087068, 7.778540059394485e-08},
    {0.16000006940003172, 0.1606824448008013, 8.658892540353068e-08},
    {0.1600000739142598, 0.16559713920073943, 9.222220444627146e-08},
    {0.16000007547383086, 0.1705118336006823, 9.417348729368973e-08},
    {0.16000007366745841, 0.17542652800062492, 9.193219180909053e-08},
    {0.1600000680852865, 0.18034122240056025, 8.498866471642774e-08},
    {0.1600000583134868, 0.18525591680047887, 7.282895332704307e-08},
    {0.16000004393654144, 0.1901706112003686, 5.493808940689439e-08},
    {0.16000002455065954, 0.1950853056002143, 3.081319743000572e-08},
    {0.15999999999999998, 0.19999999999999998, 2.5524503599060816e-19},
};
constexpr double kBentDiameter = 9.97135e-3;  // [m]

Polyline FromRows(const double (*rows)[3], int n) {
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) p.points.col(i) << rows[i][0], rows[i][1], rows[i][2];
  p.ParameteriseByChords();
  return p;
}

HarnessDrawing OneCable(const Polyline& centreline, double diameter) {
  HarnessDrawing drawing;
  DrawnCable cable;
  cable.name = "swept";
  cable.diameter = diameter;
  cable.centreline = centreline;
  drawing.cables.push_back(cable);
  return drawing;
}

// Writes `centreline` as a tube and reads it back (throws what the writer throws).
DrawnCable WriteAndReadBack(const Polyline& centreline, double diameter, const std::string& tag) {
  const std::string path = (testing::FreshTempDir(tag) / "tube.step").string();
  WriteRelaxedStep(path, OneCable(centreline, diameter), {RelaxedCable{0, centreline, diameter}});
  const HarnessDrawing back = ReadCadFile(path);
  if (back.cables.size() != 1) throw InvalidInput("expected one cable back");
  return back.cables[0];
}

// Helpers started before the sweeps are known (PrepareRelaxedStep) give the file the same tubes
// as helpers started for them.
TEST(TubeSweep, HelpersStartedAheadSweepTheSameTubes) {
  HarnessDrawing drawing;
  std::vector<RelaxedCable> cables;
  for (int k = 0; k < 16; ++k) {  // enough for two helpers
    Polyline c = FromRows(kBentSkeleton, 69);
    c.points.row(2).array() += 0.03 * k;
    drawing.cables.push_back(OneCable(c, kBentDiameter).cables[0]);
    drawing.cables.back().name = "tube" + std::to_string(k);
    cables.push_back(RelaxedCable{k, c, kBentDiameter});
  }
  const auto dir = testing::FreshTempDir("tube_sweep_ahead");
  WriteRelaxedStep((dir / "fresh.step").string(), drawing, cables);
  PrepareRelaxedStep(cables.size());
  WriteRelaxedStep((dir / "ahead.step").string(), drawing, cables);
  const HarnessDrawing fresh = ReadCadFile((dir / "fresh.step").string());
  const HarnessDrawing ahead = ReadCadFile((dir / "ahead.step").string());
  ASSERT_EQ(fresh.cables.size(), 16u);
  ASSERT_EQ(ahead.cables.size(), 16u);
  for (size_t k = 0; k < 16; ++k) {
    EXPECT_EQ(ahead.cables[k].name, fresh.cables[k].name);
    EXPECT_NEAR(ahead.cables[k].diameter, fresh.cables[k].diameter, 1e-9);
    EXPECT_LT(MaxDistanceToPolyline(ahead.cables[k].centreline, fresh.cables[k].centreline), 1e-9)
        << k;
  }
}

TEST(TubeSweep, NoisyMeshSkeletonThatCrashedThePipeSweepGivesTheTube) {
  const int n = static_cast<int>(std::size(kBentSkeleton));
  const Polyline route = FromRows(kBentSkeleton, n);
  const DrawnCable back = WriteAndReadBack(route, kBentDiameter, "sweep_skeleton");
  EXPECT_EQ(back.source, CableSourceKind::kTube);
  EXPECT_NEAR(back.diameter, kBentDiameter, 0.01 * kBentDiameter);
  EXPECT_LT(MaxDistanceToPolyline(back.centreline, route), 0.01 * kBentDiameter);
  EXPECT_LT(MaxDistanceToPolyline(route, back.centreline), 0.01 * kBentDiameter);
}

TEST(TubeSweep, RepeatedPointsAreDroppedBeforeTheSweep) {
  // Most points repeated (a stalled solver, chained edges): a zero median spacing once made the
  // gap filling divide by zero.
  const double d = 0.008;  // [m]
  Polyline route;
  route.points.resize(3, 400);
  for (int i = 0; i < 400; ++i) {
    const double t = 0.005 * (i / 4);  // each point four times [m]
    route.points.col(i) << t, 0.2 * std::sin(t), 0.0;
  }
  route.ParameteriseByChords();
  const DrawnCable back = WriteAndReadBack(route, d, "sweep_repeated");
  EXPECT_NEAR(back.diameter, d, 0.01 * d);
  EXPECT_LT(MaxDistanceToPolyline(back.centreline, route), 0.01 * d);
  EXPECT_LT(MaxDistanceToPolyline(route, back.centreline), 0.01 * d);
}

TEST(TubeSweep, CentrelineWithoutLengthIsAOneLineError) {
  Polyline route;
  route.points.resize(3, 5);
  route.points.colwise() = Eigen::Vector3d(0.1, 0.2, 0.3);
  route.points(0, 3) += 1e-7;  // [m], far below the diameter
  route.ParameteriseByChords();
  EXPECT_THROW_WITH(WriteAndReadBack(route, 0.01, "sweep_point"), InvalidInput,
                    "cable 'swept': the relaxed centreline has no length");
}

TEST(TubeSweep, ACableThatCannotBeSweptLeavesItsNeighboursInTheFile) {
  const double d = 0.01;  // [m]
  Polyline good;
  good.points.resize(3, 30);
  for (int i = 0; i < 30; ++i) good.points.col(i) << 0.01 * i, 0.02 * std::sin(0.2 * i), 0.0;
  good.ParameteriseByChords();
  Polyline point;
  point.points.resize(3, 4);
  point.points.colwise() = Eigen::Vector3d(0.1, 0.2, 0.3);
  point.ParameteriseByChords();
  HarnessDrawing drawing = OneCable(good, d);
  drawing.cables.push_back(drawing.cables[0]);
  drawing.cables[1].name = "collapsed";
  const std::string path = (testing::FreshTempDir("sweep_skip") / "two.step").string();
  EXPECT_THROW(WriteRelaxedStep(path, drawing, {RelaxedCable{0, good, d}, RelaxedCable{1, point, d}}),
               InvalidInput);
  std::vector<std::string> skipped;
  WriteRelaxedStep(path, drawing, {RelaxedCable{0, good, d}, RelaxedCable{1, point, d}}, &skipped);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0], "cable 'collapsed': the relaxed centreline has no length");
  const HarnessDrawing back = ReadCadFile(path);
  ASSERT_EQ(back.cables.size(), 1u);
  EXPECT_EQ(back.cables[0].name, "swept");
}

TEST(TubeSweep, AClosedLoopHasLengthAndIsWritten) {
  // A ring ends where it starts; its end-to-end distance is zero but its length is not.
  const double d = 0.006;  // [m]
  Polyline ring;
  const int n = 61;
  ring.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / (n - 1);
    ring.points.col(i) << 0.1 * std::cos(t), 0.1 * std::sin(t), 0.02 * std::sin(2 * t);
  }
  ring.ParameteriseByChords();
  const std::string path = (testing::FreshTempDir("sweep_ring") / "ring.step").string();
  std::vector<std::string> skipped;
  WriteRelaxedStep(path, OneCable(ring, d), {RelaxedCable{0, ring, d}}, &skipped);
  ASSERT_TRUE(skipped.empty()) << skipped.front();
  // Written as two halves (a spline through coinciding ends cannot be swept): together they are
  // the ring.
  const HarnessDrawing back = ReadCadFile(path);
  ASSERT_GE(back.cables.size(), 1u);
  double length = 0.0;  // [m]
  for (const DrawnCable& c : back.cables) {
    EXPECT_NEAR(c.diameter, d, 0.01 * d);
    length += c.centreline.ChordLength();
  }
  EXPECT_NEAR(length, ring.ChordLength(), 0.02 * ring.ChordLength());
}

// A stub shorter than its diameter (a segment between two close nodes of a harness network) has
// its ends closer than its diameter, as a closed loop has; it was written as two halves, which
// read back as two tubes. Written as one, it reads back as one (a part on its own: it is stout).
TEST(TubeSweep, AStubShorterThanItsDiameterIsOneTubeNotTwoHalves) {
  const double d = 0.0106;  // [m]
  Polyline stub;
  stub.points.resize(3, 9);
  for (int i = 0; i < 9; ++i) stub.points.col(i) << 0.001 * i, 0.0, 0.0;
  stub.ParameteriseByChords();
  const std::string path = (testing::FreshTempDir("sweep_stub") / "stub.step").string();
  WriteRelaxedStep(path, OneCable(stub, d), {RelaxedCable{0, stub, d}});
  EXPECT_THROW_WITH(ReadCadFile(path), FileError,
                    "(1 other solids); 'swept': a tube 0.8 diameters long");
}

}  // namespace
}  // namespace cablefit
