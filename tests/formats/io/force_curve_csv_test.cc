#include "cablefit/formats/force_curve_csv.h"

#include <gtest/gtest.h>

#include "cablefit/core/base/errors.h"
#include "io_test_files.h"
#include "test_support.h"

namespace cablefit {
namespace {

using testing::FreshTempDir;
using testing::WriteText;

TEST(ForceCurveCsv, ReadsPublicCurves) {
  const auto root = testing::PublicCasesDir();
  const ForceCurve bending = ReadForceCurveCsv((root / "sample-force-hysteresis" / "bending.csv").string());
  EXPECT_EQ(bending.x_name, "displacement");
  EXPECT_EQ(bending.y_name, "force");
  ASSERT_GE(bending.size(), 4);
  EXPECT_EQ(bending.step[0], 0);
  EXPECT_DOUBLE_EQ(bending.x[1], 0.0123225);
  EXPECT_DOUBLE_EQ(bending.y[0], 0.1385752);

  const ForceCurve torsion = ReadForceCurveCsv((root / "sample-force-none" / "torsion.csv").string());
  EXPECT_EQ(torsion.x_name, "angle");
  EXPECT_EQ(torsion.y_name, "moment");
  EXPECT_DOUBLE_EQ(torsion.y[0], -1.604353e-05);
  EXPECT_EQ(static_cast<int>(torsion.step.size()), torsion.size());

  const ForceCurve stiff = ReadForceCurveCsv((root / "sample-force-stiffness" / "bending.csv").string());
  EXPECT_GE(stiff.size(), 2);
}

TEST(ForceCurveCsv, RoundTripIsExact) {
  const auto dir = FreshTempDir("io");
  ForceCurve c;
  c.x_name = "angle";
  c.y_name = "moment";
  c.x = Eigen::VectorXd::LinSpaced(7, 0.0, 0.2094395102393195);
  c.y = c.x * (1.0 / 3.0);
  c.step = {0, 1, 2, 3, 5, 8, 13};
  const auto path = (dir / "t.csv").string();
  WriteForceCurveCsv(path, c);
  const ForceCurve back = ReadForceCurveCsv(path);
  EXPECT_EQ(back.x_name, "angle");
  EXPECT_EQ(back.step, c.step);
  EXPECT_EQ(back.x, c.x);
  EXPECT_EQ(back.y, c.y);

  c.step.clear();  // numbered from 0 when absent
  WriteForceCurveCsv(path, c);
  EXPECT_EQ(ReadForceCurveCsv(path).step[6], 6);
}

TEST(ForceCurveCsv, WriterRejectsBadCurves) {
  const auto dir = FreshTempDir("io");
  const auto path = (dir / "t.csv").string();
  ForceCurve c;
  c.x_name = "displacement";
  c.y_name = "moment";
  c.x = Eigen::VectorXd::Zero(2);
  c.y = Eigen::VectorXd::Zero(2);
  EXPECT_THROW_WITH(WriteForceCurveCsv(path, c), FileError, "displacement,moment");
  c.y_name = "force";
  c.y = Eigen::VectorXd::Zero(3);
  EXPECT_THROW_WITH(WriteForceCurveCsv(path, c), FileError, "different lengths");
  c.y = Eigen::VectorXd::Constant(2, std::nan(""));
  EXPECT_THROW_WITH(WriteForceCurveCsv(path, c), FileError, "non-finite");
  EXPECT_TRUE(testing::ListDir(dir).empty());
}

struct BadCsv {
  const char* label;
  const char* text;
  const char* message;
};

class ForceCurveCsvRejects : public ::testing::TestWithParam<BadCsv> {};

TEST_P(ForceCurveCsvRejects, WithMessage) {
  const auto dir = FreshTempDir(std::string("io-") + GetParam().label);
  const auto path = (dir / "f.csv").string();
  WriteText(path, GetParam().text);
  EXPECT_THROW_WITH(ReadForceCurveCsv(path), FileError, GetParam().message);
}

const BadCsv kBadCurves[] = {
    {"empty", "", "is empty"},
    {"no_step", "displacement,force\n0,1\n1,2\n", "missing column 'step'"},
    {"no_force", "step,displacement\n0,1\n1,2\n", "missing column 'force' next to 'displacement'"},
    {"no_angle", "step,moment\n0,1\n1,2\n", "missing column 'angle' next to 'moment'"},
    {"no_data", "step,time,value\n0,1,2\n1,2,3\n", "missing data columns"},
    {"one_row", "step,angle,moment\n0,0,0\n", "has 1 row(s)"},
    {"nan", "step,angle,moment\n0,0,0\n1,0.1,nan\n", "line 3, column 'moment' is NaN"},
    {"text", "step,displacement,force\n0,0,0\n1,x,1\n", "column 'displacement' is not a number: 'x'"},
    {"step", "step,displacement,force\n0,0,0\n1.5,1,1\n", "column 'step' is not an integer: '1.5'"},
    {"ragged", "step,displacement,force\n0,0,0\n1,1\n", "line 3 has 2 cells"},
};

INSTANTIATE_TEST_SUITE_P(Malformed, ForceCurveCsvRejects, ::testing::ValuesIn(kBadCurves),
                         [](const auto& info) { return std::string(info.param.label); });

}  // namespace
}  // namespace cablefit
