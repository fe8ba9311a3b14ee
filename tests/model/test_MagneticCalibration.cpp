/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The calibration's magnetic section (MagneticModel.h): file round trip and versioning, and the
// compensator's field input (bias += dph_per_uT * field_uT), checked against the closed form
// applied to the same calibration without the section.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
const Calibration& magneticBiasOnly()
{
	static const Calibration cal = fitCalibration({fogtest::makeCoilRun("A", 81)}, "multipoint");
	return cal;
}
MagneticModel magneticTerm(double dph_per_uT)
{
	MagneticModel m;
	m.dph_per_uT = dph_per_uT;
	m.dph_per_uT_std = 0.00000762939453125;  // 2^-17: written exactly with few digits
	m.field_min_uT = -50.0;
	m.field_max_uT = 100.0;
	m.samples = 4321;
	return m;
}
Calibration withMagnetic(double dph_per_uT)
{
	Calibration c = magneticBiasOnly();
	c.magnetic = magneticTerm(dph_per_uT);
	return c;
}
/** Field steps: 0, +100, 0, -50 uT, each a quarter of the run. */
std::vector<double> fieldSteps(const FogSeries& s)
{
	std::vector<double> f(s.size());
	for (std::size_t k = 0; k < f.size(); k++)
	{
		const std::size_t q = 4 * k / f.size();
		f[k] = q == 1 ? 100.0 : q == 3 ? -50.0 : 0.0;
	}
	return f;
}
std::string magneticReplaced(std::string s, const std::string& from, const std::string& to)
{
	const auto p = s.find(from);
	EXPECT_NE(p, std::string::npos) << from;
	if (p != std::string::npos) s.replace(p, from.size(), to);
	return s;
}
std::string magneticErrorOf(const std::string& text)
{
	try
	{
		calibrationFromYaml(text, "cal.yaml");
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

// The section round-trips exactly and makes the file version 3; without it the file stays 2.
TEST(MagneticCalibration, YamlRoundTripIsExactAndVersion3)
{
	const Calibration c = withMagnetic(3.0e-4 + 1e-19);
	const std::string text = calibrationToYaml(c);
	EXPECT_NE(text.find("\nversion: 3\n"), std::string::npos);
	EXPECT_NE(text.find("dph_per_uT: "), std::string::npos);
	const Calibration back = calibrationFromYaml(text, "m.yaml");
	ASSERT_TRUE(back.magnetic.has_value());
	EXPECT_EQ(back.magnetic->dph_per_uT, c.magnetic->dph_per_uT);
	EXPECT_EQ(back.magnetic->dph_per_uT_std, 0.00000762939453125);
	EXPECT_EQ(back.magnetic->field_min_uT, -50.0);
	EXPECT_EQ(back.magnetic->field_max_uT, 100.0);
	EXPECT_EQ(back.magnetic->samples, 4321u);
	EXPECT_EQ(calibrationToYaml(back), text);
	const std::string plain = calibrationToYaml(magneticBiasOnly());
	EXPECT_NE(plain.find("\nversion: 2\n"), std::string::npos);
	EXPECT_FALSE(calibrationFromYaml(plain, "p.yaml").magnetic.has_value());
}

// A file that says version 2 (or 1) but holds the section is refused: a version-2 reader would
// ignore it and compensate without the field term.
TEST(MagneticCalibration, Version2FileWithTheSectionIsRefused)
{
	const std::string text = calibrationToYaml(withMagnetic(3e-4));
	const std::string v2 = magneticReplaced(text, "\nversion: 3\n", "\nversion: 2\n");
	const std::string e = magneticErrorOf(v2);
	EXPECT_NE(e.find("cal.yaml: axes[0].magnetic: a magnetic-sensitivity section needs file version 3 (the file says 2)"),
			  std::string::npos)
		<< e;
	// version 1 (single axis at the top level): the same refusal
	std::ifstream f(std::string(FOG_TEST_DATA_DIR) + "/model/cal_v1_coil_A.yaml");
	std::string v1((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	ASSERT_EQ(magneticErrorOf(v1), "");
	v1 += "magnetic:\n  dph_per_uT: 0.0003\n";
	EXPECT_NE(magneticErrorOf(v1).find("cal.yaml: magnetic: a magnetic-sensitivity section needs file version 3 (the file says 1)"),
			  std::string::npos)
		<< magneticErrorOf(v1);
}

// Bad numbers in the section are field errors naming the key.
TEST(MagneticCalibration, BadSectionGivesFieldErrors)
{
	const std::string good = calibrationToYaml(withMagnetic(0.000244140625));  // 2^-12
	ASSERT_EQ(magneticErrorOf(good), "");
	const struct
	{
		std::string from, to, field;
	} cases[] = {
		{"dph_per_uT: 0.000244140625 ", "dph_per_uT: .nan ", "axes[0].magnetic.dph_per_uT"},
		{"dph_per_uT_std: 7.62939453125e-06 ", "dph_per_uT_std: -1e-05 ", "axes[0].magnetic.dph_per_uT_std: must be >= 0"},
		{"dph_per_uT_std: 7.62939453125e-06 ", "dph_per_uT_std: .inf ", "axes[0].magnetic.dph_per_uT_std"},
		{"field_range_uT: [-50, 100]", "field_range_uT: [100, -50]", "axes[0].magnetic.field_range_uT: min > max"},
		{"field_range_uT: [-50, 100]", "field_range_uT: [-50]", "axes[0].magnetic.field_range_uT: expected [min, max]"},
		{"field_range_uT: [-50, 100]", "field_range_uT: [-50, .inf]", "axes[0].magnetic.field_range_uT"},
	};
	for (const auto& c : cases)
	{
		const std::string e = magneticErrorOf(magneticReplaced(good, c.from, c.to));
		EXPECT_NE(e.find(c.field), std::string::npos) << c.to << " -> " << e;
	}
	Calibration bad = withMagnetic(0.000244140625);
	bad.magnetic->dph_per_uT_std = -1;
	EXPECT_THROW(calibrationToYaml(bad), std::invalid_argument);
}

// Constant bias model plus k x field steps: compensated == raw - (bias model + k field) exactly,
// bias == bias model + k field; the field-less compensation of the same calibration is unchanged.
TEST(MagneticCalibration, CompensatorFollowsTheClosedForm)
{
	const double k = 4e-4;
	FogSeries b = fogtest::makeCoilRun("B", 82);
	const CompensatedSeries plain = compensate(magneticBiasOnly(), b);
	b.field_uT = fieldSteps(b);
	const CompensatedSeries out = compensate(withMagnetic(k), b);
	ASSERT_EQ(out.counters.field_unknown_samples, 0u);
	for (std::size_t i = 0; i < b.size(); i++)
	{
		const double bias = plain.bias_dph[i] + k * b.field_uT[i];
		ASSERT_EQ(out.bias_dph[i], bias) << i;
		ASSERT_EQ(out.compensated_dph[i], b.rate_dph[2][i] - bias) << i;
	}
	// the plain calibration ignores the field column
	EXPECT_EQ(compensate(magneticBiasOnly(), b).compensated_dph, plain.compensated_dph);
}

// Field unknown (no column, NaN samples, or never noted): no term, and the samples are counted.
TEST(MagneticCalibration, UnknownFieldIsCountedAndAddsNothing)
{
	FogSeries b = fogtest::makeCoilRun("B", 83);
	const CompensatedSeries plain = compensate(magneticBiasOnly(), b);
	const Calibration cal = withMagnetic(4e-4);
	const CompensatedSeries none = compensate(cal, b);  // no field column
	EXPECT_EQ(none.compensated_dph, plain.compensated_dph);
	EXPECT_EQ(none.counters.field_unknown_samples, b.size());
	EXPECT_NE(fieldMissingWarning(cal, b).find("no field column"), std::string::npos);
	EXPECT_EQ(fieldMissingWarning(magneticBiasOnly(), b), "");
	EXPECT_EQ(compensate(magneticBiasOnly(), b).counters.field_unknown_samples, 0u);
	b.field_uT = fieldSteps(b);
	for (std::size_t i = 0; i < 100; i++) b.field_uT[i] = std::numeric_limits<double>::quiet_NaN();
	const CompensatedSeries some = compensate(cal, b);
	EXPECT_EQ(some.counters.field_unknown_samples, 100u);
	EXPECT_EQ(fieldMissingWarning(cal, b), "");
	for (std::size_t i = 0; i < b.size(); i++)
		ASSERT_EQ(some.bias_dph[i], plain.bias_dph[i] + (i < 100 ? 0.0 : 4e-4 * b.field_uT[i])) << i;
	// streaming: never noted -> unknown; a noted field is held; reset() forgets it
	Compensator comp(cal, b.thermistors);
	std::vector<double> row(b.thermistorCount());
	const auto rowAt = [&](std::size_t i) {
		for (std::size_t c = 0; c < row.size(); c++) row[c] = b.temp_C[c][i];
		return row.data();
	};
	EXPECT_EQ(comp.step(b.time_s[0], b.rate_dph[2][0], rowAt(0)).bias_dph, plain.bias_dph[0]);
	comp.noteField(100.0);
	EXPECT_EQ(comp.step(b.time_s[1], b.rate_dph[2][1], rowAt(1)).bias_dph, plain.bias_dph[1] + 4e-4 * 100.0);
	EXPECT_EQ(comp.step(b.time_s[2], b.rate_dph[2][2], rowAt(2)).bias_dph, plain.bias_dph[2] + 4e-4 * 100.0);
	EXPECT_EQ(comp.counters().field_unknown_samples, 1u);
	comp.reset();
	comp.step(b.time_s[0], b.rate_dph[2][0], rowAt(0));
	EXPECT_EQ(comp.counters().field_unknown_samples, 1u);
	EXPECT_TRUE(comp.readsField());
	EXPECT_FALSE(Compensator(magneticBiasOnly(), b.thermistors).readsField());
}

// Batch (compensate) == streaming (noteField + step per sample) with the field, bit for bit,
// for both builds of the per-sample code.
TEST(MagneticCalibration, BatchEqualsStreamingWithTheField)
{
	FogSeries b = fogtest::makeCoilRun("B", 84);
	b.field_uT = fieldSteps(b);
	for (std::size_t i = 0; i < b.size(); i++) b.field_uT[i] += 0.01 * static_cast<double>(i % 37);  // varies per sample
	const Calibration cal = withMagnetic(-3e-4);
	const CompensatedSeries batch = compensate(cal, b);
	for (KernelBuild kb : {KernelBuild::Portable, KernelBuild::Auto})
	{
		Compensator comp(cal, b.thermistors, kb);
		std::vector<double> row(b.thermistorCount());
		for (std::size_t i = 0; i < b.size(); i++)
		{
			for (std::size_t c = 0; c < row.size(); c++) row[c] = b.temp_C[c][i];
			comp.noteField(b.field_uT[i]);
			const Compensator::Output o = comp.step(b.time_s[i], b.rate_dph[2][i], row.data());
			ASSERT_EQ(o.bias_dph, batch.bias_dph[i]) << i;
			ASSERT_EQ(o.compensated_dph, batch.compensated_dph[i]) << i;
			ASSERT_EQ(o.flags, batch.flags[i]) << i;
		}
		EXPECT_EQ(comp.counters().field_unknown_samples, 0u);
	}
}

// The term's contribution is bounded, not only its coefficient: |dph_per_uT| x 1e4 uT (the
// largest field a log may hold) must stay within 1e6 deg/h (was: 1e6 deg/h per uT accepted,
// a bias of 5e7 deg/h at 50 uT); a recorded field range beyond 1e4 uT is refused.
TEST(MagneticCalibration, TermContributionIsBounded)
{
	const std::string good = calibrationToYaml(withMagnetic(0.000244140625));
	const auto withCoef = [&](const std::string& v) {
		return magneticReplaced(good, "dph_per_uT: 0.000244140625 ", "dph_per_uT: " + v + " ");
	};
	EXPECT_EQ(magneticErrorOf(withCoef("100")), "");  // 1e6 deg/h at 1e4 uT: the bound itself
	for (const char* v : {"100.5", "1000000", "-1000000"})
	{
		const std::string e = magneticErrorOf(withCoef(v));
		EXPECT_NE(e.find("axes[0].magnetic.dph_per_uT"), std::string::npos) << v << " -> " << e;
		EXPECT_NE(e.find("at 10000 uT"), std::string::npos) << v << " -> " << e;
	}
	const std::string e = magneticErrorOf(magneticReplaced(good, "field_range_uT: [-50, 100]", "field_range_uT: [-50, 20000]"));
	EXPECT_NE(e.find("axes[0].magnetic.field_range_uT: beyond the plausible field of 10000 uT"), std::string::npos) << e;
}

// Fields outside the calibration's recorded range [-50, 100] uT are counted, with the largest
// distance beyond it, as temperatures outside the calibrated range are; the term still applies.
TEST(MagneticCalibration, FieldOutsideTheRecordedRangeIsCounted)
{
	FogSeries b = fogtest::makeCoilRun("B", 85);
	b.field_uT = fieldSteps(b);
	const Calibration cal = withMagnetic(4e-4);
	const CompensatedSeries inside = compensate(cal, b);
	EXPECT_EQ(inside.counters.field_outside_samples, 0u);
	EXPECT_EQ(inside.counters.max_field_excursion_uT, 0.0);
	for (std::size_t i = 0; i < 10; i++) b.field_uT[i] = 150.0;  // 50 uT above
	for (std::size_t i = 10; i < 13; i++) b.field_uT[i] = -80.0;  // 30 uT below
	const CompensatedSeries out = compensate(cal, b);
	EXPECT_EQ(out.counters.field_outside_samples, 13u);
	EXPECT_EQ(out.counters.max_field_excursion_uT, 50.0);
	const CompensatedSeries plain = compensate(magneticBiasOnly(), b);
	EXPECT_EQ(out.bias_dph[0], plain.bias_dph[0] + 4e-4 * 150.0);
}
