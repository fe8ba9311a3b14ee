/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RowSpill.h
 * Rows of a fixed number of doubles, appended in order and read back in sequential passes, with
 * memory that does not grow with the number of rows (programs whose analysis needs
 * several passes over a log keep it here instead of in columns). The first kBlockRows rows stay
 * in memory; beyond that, full blocks go to a temporary file created in $TMPDIR (else /tmp) with
 * mkstemp and unlinked at once, so nothing is left behind whatever happens to the process (the
 * disk space is returned when the RowSpill is destroyed or the process ends). The values read
 * back are bit-identical to those appended.
 *
 *   RowSpill s(3);                       // 3 doubles per row
 *   s.push(row);  ...                    // append
 *   s.forEachBlock([&](const double* rows, std::size_t n, std::size_t first_row) { ... });
 *
 * Disk use: 8 x width bytes per row beyond the first block (write errors, e.g. a full disk, throw
 * std::runtime_error naming the file system error). */

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mrpt_fog
{
class RowSpill
{
   public:
	static constexpr std::size_t kBlockRows = 1u << 15;  //!< rows per block (in memory and per file read)

	explicit RowSpill(std::size_t width);
	~RowSpill();
	RowSpill(RowSpill&&) noexcept;
	RowSpill& operator=(RowSpill&&) noexcept;
	RowSpill(const RowSpill&) = delete;
	RowSpill& operator=(const RowSpill&) = delete;

	std::size_t width() const { return width_; }
	std::size_t rows() const { return rows_; }
	/** True once rows went to the temporary file. */
	bool onDisk() const { return fd_ >= 0; }

	/** Appends one row of width() doubles. */
	void push(const double* row);

	/** Calls f(rows, n, first_row) for consecutive blocks of n rows (row-major, n x width()
	 * doubles), in order, covering every row pushed so far. */
	void forEachBlock(const std::function<void(const double* rows, std::size_t n, std::size_t first_row)>& f) const;

	/** Pull-style sequential reader (several may read one RowSpill at once, each at its own
	 * position; the RowSpill must not change while they read). */
	class Reader
	{
	   public:
		explicit Reader(const RowSpill& s);
		/** The next row (width() doubles, valid until the next call), or nullptr at the end. */
		const double* next();
		std::size_t position() const { return pos_; }  //!< rows returned so far

	   private:
		const RowSpill& s_;
		std::vector<double> buf_;
		const double* block_ = nullptr;
		std::size_t block_first_ = 0, block_rows_ = 0, pos_ = 0;
	};

   private:
	void flushBlock();
	void readFileRows(double* to, std::size_t first_row, std::size_t n) const;
	std::size_t width_;
	std::size_t rows_ = 0;
	std::size_t file_rows_ = 0;  // rows in the file (whole blocks)
	std::vector<double> block_;  // the last, partial block (rows_ - file_rows_ rows)
	int fd_ = -1;
	std::string dir_;
};

}  // namespace mrpt_fog
