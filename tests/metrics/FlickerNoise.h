/* Test generator: flicker (1/f) rate noise of known bias instability B, independent of the
 * estimator under test.
 *
 * Kasdin's discrete 1/f noise (Proc. IEEE 83(5):802, 1995): white innovations w of sigma B
 * filtered by h_0 = 1, h_k = h_{k-1} (k - 1/2) / k. Its two-sided PSD is
 * B^2 tau_f / (2 sin(pi f tau_f)) ~ B^2 / (2 pi f) for f << 1/tau_f: exactly IEEE 952's flicker
 * PSD (B^2 / 2 pi)(1/f), so B is the innovation sigma. A point-sampled 1/f sequence has an Allan
 * excess at the shortest taus (its spectrum rises above 1/f near Nyquist: AVAR/AVAR_inf =
 * (1/ln2) int_0^{pi/2} sin^4(m u)/(m^2 sin^3 u) du = 1.443, 1.154, 1.050 at m = 1, 2, 4); a gyro
 * output sample is the mean rate over its period, so the generator runs on a grid `oversample`
 * times finer and returns block means (excess at the output's m = 1: the fine grid's m = 8:
 * +0.8 % in deviation; m = 16: +0.2 %). The filter starts from rest; a burn-in of `n` output
 * samples is generated and dropped so the kept record is close to stationary. */
#pragma once

#include <unsupported/Eigen/FFT>

#include <complex>
#include <cstddef>
#include <random>
#include <vector>

namespace fog_test
{
inline std::vector<double> flickerRate(std::size_t n, double b_dph, std::size_t oversample, std::mt19937_64& rng)
{
	const std::size_t nf = 2 * n * oversample;  // burn-in + kept record, fine grid
	std::size_t len = 1;
	while (len < 2 * nf) len <<= 1;
	std::vector<double> h(len, 0.0), w(len, 0.0);
	h[0] = 1.0;
	for (std::size_t k = 1; k < nf; k++) h[k] = h[k - 1] * (static_cast<double>(k) - 0.5) / static_cast<double>(k);
	std::normal_distribution<double> g(0.0, b_dph);
	for (std::size_t k = 0; k < nf; k++) w[k] = g(rng);
	Eigen::FFT<double> fft;
	std::vector<std::complex<double>> H, W;
	fft.fwd(H, h);
	fft.fwd(W, w);
	for (std::size_t k = 0; k < H.size(); k++) H[k] *= W[k];
	std::vector<double> x;
	fft.inv(x, H);  // linear convolution: len >= 2 nf, no wrap-around
	std::vector<double> y(n, 0.0);
	const std::size_t start = n * oversample;
	for (std::size_t i = 0; i < n; i++)
	{
		double s = 0;
		for (std::size_t j = 0; j < oversample; j++) s += x[start + i * oversample + j];
		y[i] = s / static_cast<double>(oversample);
	}
	return y;
}
}  // namespace fog_test
