/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/common/RowSpill.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

#include <unistd.h>

using namespace mrpt_fog;

// Rows beyond the first block go to an unlinked temporary file: read back bit for bit (NaN
// payloads, -0, denormals included), by block and by several independent readers, and nothing is
// left in TMPDIR.
TEST(RowSpill, RowsComeBackBitForBitAndNoFileIsLeft)
{
	namespace fs = std::filesystem;
	const fs::path dir = fs::temp_directory_path() / ("rowspill_test_" + std::to_string(::getpid()));
	fs::create_directories(dir);
	const char* old = std::getenv("TMPDIR");
	const std::string saved = old ? old : "";
	::setenv("TMPDIR", dir.c_str(), 1);
	{
		RowSpill s(3);
		const std::size_t n = 2 * RowSpill::kBlockRows + 123;
		const auto value = [](std::size_t k, std::size_t c) {
			if (k % 1000 == 7) return std::numeric_limits<double>::quiet_NaN();
			if (k % 1000 == 8) return -0.0;
			if (k % 1000 == 9) return std::numeric_limits<double>::denorm_min() * static_cast<double>(c + 1);
			return std::sin(static_cast<double>(k) * 0.37 + static_cast<double>(c));
		};
		for (std::size_t k = 0; k < n; k++)
		{
			const double row[3] = {value(k, 0), value(k, 1), value(k, 2)};
			s.push(row);
		}
		EXPECT_TRUE(s.onDisk());
		EXPECT_EQ(s.rows(), n);
		EXPECT_TRUE(fs::is_empty(dir));  // unlinked at once
		std::size_t seen = 0, bad = 0;
		s.forEachBlock([&](const double* r, std::size_t m, std::size_t first) {
			EXPECT_EQ(first, seen);
			for (std::size_t j = 0; j < m; j++, seen++)
				for (std::size_t c = 0; c < 3; c++)
				{
					const double want = value(seen, c);
					bad += std::memcmp(&r[3 * j + c], &want, sizeof want) != 0;
				}
		});
		EXPECT_EQ(seen, n);
		EXPECT_EQ(bad, 0u);
		RowSpill::Reader a(s), b(s);
		for (std::size_t k = 0; k < 10; k++) b.next();
		for (std::size_t k = 0; k + 10 < n; k++)
		{
			const double* ra = a.next();
			ASSERT_NE(ra, nullptr);
			const double want = value(k, 1);
			ASSERT_EQ(std::memcmp(&ra[1], &want, sizeof want), 0) << k;
			const double* rb = b.next();
			ASSERT_NE(rb, nullptr);
			const double wantb = value(k + 10, 2);
			ASSERT_EQ(std::memcmp(&rb[2], &wantb, sizeof wantb), 0) << k;
		}
		EXPECT_EQ(b.next(), nullptr);
	}
	if (old) ::setenv("TMPDIR", saved.c_str(), 1);
	else ::unsetenv("TMPDIR");
	EXPECT_TRUE(fs::is_empty(dir));
	fs::remove_all(dir);
}

TEST(RowSpill, ShortSpillStaysInMemoryAndAMissingTmpdirIsAClearError)
{
	RowSpill s(2);
	const double row[2] = {1, 2};
	s.push(row);
	EXPECT_FALSE(s.onDisk());
	std::size_t n = 0;
	s.forEachBlock([&](const double* r, std::size_t m, std::size_t) {
		n += m;
		EXPECT_EQ(r[1], 2.0);
	});
	EXPECT_EQ(n, 1u);
	const char* old = std::getenv("TMPDIR");
	const std::string saved = old ? old : "";
	::setenv("TMPDIR", "/nonexistent/dir", 1);
	RowSpill t(1);
	const double x = 0;
	try
	{
		for (std::size_t k = 0; k <= RowSpill::kBlockRows; k++) t.push(&x);
		ADD_FAILURE() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/dir"), std::string::npos) << e.what();
	}
	if (old) ::setenv("TMPDIR", saved.c_str(), 1);
	else ::unsetenv("TMPDIR");
}
