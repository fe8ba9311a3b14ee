/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog_heading/FogMotionModel.h>

#include <cmath>

namespace mrpt_fog::heading
{
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions FogMotionModel::toMrpt(double dt_s) const
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
	m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	auto& g = m.gaussianModel;
	g.a1 = distance_frac;  // [m/m]
	g.a2 = 0.0;  // no position noise from turning
	g.a3 = 0.0;  // no heading noise per metre: the heading is the FOG's, not the wheels'
	g.a4 = scale_factor_ppm * 1e-6;  // [rad/rad]
	g.minStdXY = min_std_xy_m;
	g.minStdPHI = heading_bias_dph / 3600.0 * M_PI / 180.0 * std::sqrt(dt_s * horizon_s);  // [rad]
	return m;
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions wheelMotionModel()
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;  // MRPT's defaults, gaussianModel included
	m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	return m;
}

}  // namespace mrpt_fog::heading
