/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file MagneticModel.h
 * The magnetic (Faraday) sensitivity of one gyro axis: an axial magnetic field B adds a bias
 *
 *   magnetic_dph = dph_per_uT * B_uT,
 *
 * on top of the thermal bias model (the field rotates the polarisation in the fibre; a shielded
 * coil keeps dph_per_uT around 1e-4 .. 1e-3). The field is not a temperature: the compensator
 * reads it from its own input (Compensator::noteField, FogSeries::field_uT); while the field is
 * unknown no magnetic term is added and the samples are counted. Fitted from runs with field
 * segments by discrepancy/MagneticFit.h: fog-calibrate (--magnetic auto) and the model-gap
 * workflow's --write-cal (discrepancy/CalibrationAugment.h).
 */

#include <cmath>
#include <cstddef>

namespace mrpt_fog
{
struct MagneticModel
{
	double dph_per_uT = 0.0;  //!< bias per axial field [deg/h per uT]
	double dph_per_uT_std = 0.0;  //!< standard error of dph_per_uT [deg/h per uT] (>= 0)
	/** Applied field range of the fitting data [uT] (min <= max); the term is applied outside it
	 * too (a linear effect), the range says what the coefficient was seen on. */
	double field_min_uT = 0.0, field_max_uT = 0.0;
	std::size_t samples = 0;  //!< samples of the fit

	/** The term [deg/h] at field_uT (NaN in -> NaN out). */
	double bias_dph(double field_uT) const { return dph_per_uT * field_uT; }
	/** Finite coefficient and range, std >= 0, min <= max. */
	bool valid() const
	{
		return std::isfinite(dph_per_uT) && std::isfinite(dph_per_uT_std) && dph_per_uT_std >= 0 &&
			   std::isfinite(field_min_uT) && std::isfinite(field_max_uT) && field_min_uT <= field_max_uT;
	}
};

}  // namespace mrpt_fog
