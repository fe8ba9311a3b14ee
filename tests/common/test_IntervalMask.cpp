/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* IntervalMask (internal/mrpt_fog/common/IntervalMask.h): the same flags as a std::vector<bool>
 * under random and sequential changes, a few words for a few stretches, never more than about
 * one bit per row. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/IntervalMask.h>

#include <random>

using mrpt_fog::IntervalMask;

TEST(IntervalMask, SameFlagsAsABitVector)
{
	for (const bool start : {true, false})
	{
		const std::size_t n = 5000;
		IntervalMask m;
		m.assign(n, start);
		std::vector<bool> ref(n, start);
		std::mt19937 rng(start ? 1 : 2);
		std::uniform_int_distribution<std::size_t> at(0, n - 1);
		for (int op = 0; op < 20000; op++)
		{
			const std::size_t k = at(rng);
			const bool v = (rng() & 1u) != 0;
			m.set(k, v);
			ref[k] = v;
			if (op % 1000 == 0)
				for (std::size_t j = 0; j < n; j++) ASSERT_EQ(m[j], ref[j]) << "op " << op << " row " << j;
		}
		std::size_t c = 0;
		for (std::size_t j = 0; j < n; j++)
		{
			ASSERT_EQ(m[j], ref[j]) << j;
			c += ref[j];
		}
		EXPECT_EQ(m.count(), c);
	}
}

TEST(IntervalMask, FewStretchesCostAFewWords)
{
	// 28.8 M rows, unusable at the start (rate warm-up) and in two stretches, set in row order
	const std::size_t n = 28800000;
	IntervalMask m;
	m.assign(n, true);
	for (std::size_t k = 0; k < n; k++)
		if (k < 30000 || (k >= 1000000 && k < 1200000) || (k >= 20000000 && k < 20000005)) m.set(k, false);
	EXPECT_FALSE(m.usesBits());
	EXPECT_LE(m.bytes(), 256u);
	EXPECT_EQ(m.count(), n - 30000 - 200000 - 5);
	EXPECT_FALSE(m[0]);
	EXPECT_TRUE(m[30000]);
	EXPECT_FALSE(m[1199999]);
	EXPECT_TRUE(m[1200000]);
	EXPECT_FALSE(m[20000004]);
	EXPECT_TRUE(m[n - 1]);
}

TEST(IntervalMask, FlippingFlagsFallBackToBits)
{
	const std::size_t n = 100000;
	IntervalMask m;
	m.assign(n, true);
	for (std::size_t k = 0; k < n; k += 2) m.set(k, false);
	EXPECT_TRUE(m.usesBits());
	EXPECT_LE(m.bytes(), n / 8 + 64);
	for (std::size_t k = 0; k < n; k++) ASSERT_EQ(m[k], k % 2 == 1) << k;
}
