/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

namespace mrpt_fog
{
/** Golden-section search for the minimum of a unimodal f on [a, b]: `iters` narrowing steps
 * after the two first evaluations (f(c) before f(d)); returns the better of the last two
 * interior points. */
template <class F>
double goldenSectionMinimum(F&& f, double a, double b, int iters)
{
	const double g = 0.6180339887498949;  // (sqrt(5) - 1) / 2
	double c = b - g * (b - a), d = a + g * (b - a);
	double fc = f(c), fd = f(d);
	for (int i = 0; i < iters; ++i)
	{
		if (fc < fd)
		{
			b = d;
			d = c;
			fd = fc;
			c = b - g * (b - a);
			fc = f(c);
		}
		else
		{
			a = c;
			c = d;
			fc = fd;
			d = a + g * (b - a);
			fd = f(d);
		}
	}
	return fc < fd ? c : d;
}
}  // namespace mrpt_fog
