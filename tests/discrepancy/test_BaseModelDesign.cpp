/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include "support/SyntheticChamberRun.h"

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
struct Fixture
{
	SyntheticRun run;
	RunSignals sig;
	Fixture()
	{
		run = makeSyntheticChamberRun(30);
		sig = computeRunSignals(run.series);
	}
};
}  // namespace

TEST(BaseModelDesign, StaticPresetColumns)
{
	Fixture f;
	const auto spec = resolveBaseModel("static:3", f.run.series);
	const auto d = buildBaseDesign(spec, f.run.series, f.sig);
	// constant, x, x^2, x^3 and the table-rate nuisance column (the all_conditions profile has a table)
	EXPECT_EQ(d.names, (std::vector<std::string>{"1", "T(mean)^1", "T(mean)^2", "T(mean)^3", "table_rate*1e-6"}));
	EXPECT_EQ(d.max_static_order, 3);
	EXPECT_EQ(d.is_static_temp, (std::vector<unsigned char>{0, 1, 1, 1, 0}));
	const std::size_t k = 100;
	const double x = (f.sig.temp_mean_C[k] - 20.0) / 50.0;
	EXPECT_NEAR(d.X(k, 3), x * x * x, 1e-12);
}

TEST(BaseModelDesign, ModelRoomPresetsResolve)
{
	Fixture f;
	const auto mp = buildBaseDesign(resolveBaseModel("multipoint", f.run.series), f.run.series, f.sig);
	// 4 thermistors x (5 temperature + 3 rate terms) + constant + table nuisance
	EXPECT_EQ(mp.X.cols(), 4 * 8 + 2);
	EXPECT_EQ(mp.max_static_order, 5);
	const auto m2 = buildBaseDesign(resolveBaseModel("M2:Ti1", f.run.series), f.run.series, f.sig);
	EXPECT_EQ(m2.X.cols(), 1 + 5 + 3 + 1);
	const auto m4 = buildBaseDesign(resolveBaseModel("M4:Ti1,To1", f.run.series), f.run.series, f.sig);
	EXPECT_EQ(m4.max_static_order, 0);
}

TEST(BaseModelDesign, BadPresetsThrow)
{
	Fixture f;
	EXPECT_THROW(resolveBaseModel("static:x", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("static:3:Nope", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("M2:Nope", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("quadratic", f.run.series), std::invalid_argument);
	EXPECT_ANY_THROW(resolveBaseModel("/nonexistent/cal.yaml", f.run.series));
}
