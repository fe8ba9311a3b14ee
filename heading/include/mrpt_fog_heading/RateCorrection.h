/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file RateCorrection.h
 * The pipeline's place for an in-field correction of the compensated rate, between the thermal
 * model and the Earth-rate / strapdown step (HeadingPipeline.h): e.g. standstill detection and a
 * recursive estimate of the turn-on bias offset. The pipeline calls correct() once per FOG
 * sample, in time order, with the sample, the latest wheel odometry and the compensator's
 * uncertainty, and integrates what it returns. noteOdometry() sees every wheel odometry sample
 * as it arrives. A correction must be causal (only what it was given so far). */

#include <cstdint>
#include <limits>

namespace mrpt_fog::heading
{
/** A wheel odometry sample as the pipeline received it. */
struct WheelOdometry
{
	double t_s = 0.0;  //!< absolute time [s]
	double x_m = 0.0, y_m = 0.0, phi_rad = 0.0;  //!< cumulative pose (CObservationOdometry::odometry)
	double distance_m = 0.0;  //!< signed arc length since the previous sample (0 for the first)
	double dphi_rad = 0.0;  //!< wheel heading change since the previous sample
	double dt_s = 0.0;  //!< time since the previous sample (0 for the first)
};

/** What a correction sees for one FOG sample. */
struct RateCorrectionInput
{
	double t_s = 0.0;  //!< absolute time [s]
	double raw_dph = std::numeric_limits<double>::quiet_NaN();  //!< gyro output (NaN while off)
	double compensated_dph = std::numeric_limits<double>::quiet_NaN();  //!< after the thermal model
	/** 1-sigma uncertainty of the compensated rate's bias [deg/h]: the thermal model's
	 * (thermalModelSigma_dph, StandstillCorrection.h) and the calibration's field offset's
	 * (PipelineOptions::field_offset) combined; NaN without a calibration */
	double compensation_sigma_dph = std::numeric_limits<double>::quiet_NaN();
	/** what the compensated rate reads on a still, level vehicle [deg/h]: the drive's vertical
	 * Earth rate minus the calibration's add-back (CalibrationEarthRate.h) */
	double still_reading_dph = 0.0;
	std::uint8_t compensation_flags = 0;  //!< CompensationFlag bits
	bool gyro_on = true;  //!< false on a gyro-off sample (obs/GyroPower.h)
	bool turn_on = false;  //!< the first powered sample after gyro-off ones
	/** the latest wheel odometry at or before t_s (null before the first) */
	const WheelOdometry* odometry = nullptr;
};

class RateCorrection
{
   public:
	virtual ~RateCorrection() = default;
	/** The corrected rate [deg/h] for this sample (return in.compensated_dph to change nothing).
	 * Called for every sample; the value is integrated only when in.gyro_on. */
	virtual double correct(const RateCorrectionInput& in) = 0;
	/** Every wheel odometry sample, in arrival order (before the FOG samples that follow it). */
	virtual void noteOdometry(const WheelOdometry& /*odometry*/) {}
};

}  // namespace mrpt_fog::heading
