/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/model/Calibration.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace mrpt_fog
{
constexpr EnumName<EarthRateHandling> kEarthRateHandlings[] = {{EarthRateHandling::InBias, "in_bias"},
																 {EarthRateHandling::InTableRate, "in_table_rate"}};

const char* toString(EarthRateHandling h) { return nameIn(kEarthRateHandlings, h, "in_bias"); }

EarthRateHandling earthRateHandlingFromString(const std::string& text)
{
	if (const auto h = valueIn(kEarthRateHandlings, text)) return *h;
	throw std::invalid_argument("'" + text + "' is not in_bias or in_table_rate");
}

const Calibration* CalibrationSet::forAxis(GyroAxis axis) const
{
	for (const auto& c : axes)
		if (c.axis == axis) return &c;
	return nullptr;
}

void CalibrationSet::validate() const
{
	if (axes.empty() || axes.size() > 3) throw std::invalid_argument("a calibration set holds 1 to 3 axes");
	const Calibration& a = axes.front();
	const auto sameLatitude = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
	for (std::size_t i = 0; i < axes.size(); i++)
	{
		const Calibration& c = axes[i];
		const std::string who = std::string("axis ") + axisLetter(c.axis);
		for (std::size_t j = 0; j < i; j++)
			if (axes[j].axis == c.axis) throw std::invalid_argument(who + " is calibrated twice");
		if (c.sensor_label != a.sensor_label) throw std::invalid_argument(who + ": another sensor label than the first axis");
		if (c.layout != a.layout) throw std::invalid_argument(who + ": another thermistor layout than the first axis");
		if (!sameLatitude(c.latitude_deg, a.latitude_deg) || c.earth_rate != a.earth_rate)
			throw std::invalid_argument(who + ": another latitude or Earth-rate handling than the first axis");
		if (c.magnetic && !c.magnetic->valid())
			throw std::invalid_argument(who + ": magnetic section: the coefficient and field range must be finite, "
											  "the standard deviation >= 0 and min <= max");
	}
}

double commonLatitude_deg(const std::vector<FogSeries>& runs)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	double lat = nan;
	for (std::size_t i = 0; i < runs.size(); i++)
	{
		const std::string text = runs[i].metadataValue("latitude_deg");
		char* end = nullptr;
		const double v = text.empty() ? nan : std::strtod(text.c_str(), &end);
		if (!std::isfinite(v) || *end != '\0' || std::abs(v) > 90) return nan;
		if (i > 0 && v != lat) return nan;
		lat = v;
	}
	return lat;
}

}  // namespace mrpt_fog
