/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file StandstillCorrection.h
 * The pipeline's in-field correction (RateCorrection.h) by standstill updates of the turn-on
 * bias offset: mrpt_fog_nav's FieldBiasRefiner (standstill detection from the wheel odometry
 * and the gyro, the Kalman filter of the offset, the significance rule) behind the pipeline's
 * per-sample interface. The correction of a sample at t uses only the standstill samples the
 * refiner has decided by then (all at or before t - guard): causal. Its prior: 0 +- the
 * calibration's uncertainty (RateCorrectionInput::compensation_sigma_dph: thermalModelSigma_dph,
 * with a field offset's) and the turn-on repeatability combined. HeadingPipeline installs one by
 * default when it has a calibration (PipelineOptions::field_refinement). */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog_heading/RateCorrection.h>
#include <mrpt_fog_nav/FieldBiasRefiner.h>

#include <memory>
#include <optional>

namespace mrpt_fog::heading
{
struct StandstillCorrectionOptions
{
	double turn_on_repeatability_dph = 1.0;  //!< 1-sigma, with the calibration's uncertainty the prior [deg/h]
	nav::GyroNoiseModel noise;
	nav::StandstillOptions standstill;
	double min_still_s = 10.0, guard_s = 1.0;
	double significance_sigma = 3.0;  //!< see nav::FieldRefinementOptions
};

/** The thermal model's uncertainty, the part of the prior the calibration gives [deg/h]: its
 * held-out 100 s stability (the std of 100 s averages of its compensated output on runs it was
 * not fitted to: what a bias offset is uncertain by, without the per-sample noise), else the
 * in-sample one, else 0. */
double thermalModelSigma_dph(const Calibration& cal);

class StandstillCorrection : public RateCorrection
{
   public:
	explicit StandstillCorrection(const StandstillCorrectionOptions& options = {}) : opt_(options) {}

	double correct(const RateCorrectionInput& in) override;
	void noteOdometry(const WheelOdometry& odometry) override;

	/** The refiner (null before the first sample): its updates(), filter(), applied(). */
	const nav::FieldBiasRefiner* refiner() const { return refiner_.get(); }
	/** Flushes what waits for odometry (call at the end of the log, for the last updates). */
	void finish();

   private:
	StandstillCorrectionOptions opt_;
	std::unique_ptr<nav::FieldBiasRefiner> refiner_;
	double still_reading_dph_ = 0.0;
	std::optional<WheelOdometry> early_;  //!< the last odometry before the first FOG sample
	void drain();
};

}  // namespace mrpt_fog::heading
