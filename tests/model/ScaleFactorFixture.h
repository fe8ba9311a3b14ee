/* mrpt_fog: a hand-made scale-factor model for the tests of the compensator and the calibration
 * file (the range and normalisation a fit on the synthetic coil runs would give). */
#pragma once

#include <mrpt_fog/model/Calibration.h>

#include <string>
#include <utility>
#include <vector>

namespace fogtest
{
/** A scale-factor model on `thermistor`: s(x) = sum coef_ppm[k] x^k [ppm] with x = (T - 10 C) / 50 C,
 * calibrated over -40..60 C. */
inline mrpt_fog::ScaleFactorModel scaleFactorModel(const std::string& thermistor, std::vector<double> coef_ppm)
{
	mrpt_fog::ScaleFactorModel m;
	m.thermistor = thermistor;
	m.centre_C = 10.0;
	m.scale_C = 50.0;
	m.min_C = -40.0;
	m.max_C = 60.0;
	m.coef_ppm = std::move(coef_ppm);
	return m;
}
}  // namespace fogtest
