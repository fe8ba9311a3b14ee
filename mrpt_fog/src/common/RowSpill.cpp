/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/RowSpill.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace mrpt_fog
{
namespace
{
std::string spillDir()
{
	const char* d = std::getenv("TMPDIR");
	return d && *d ? d : "/tmp";
}
}  // namespace

RowSpill::RowSpill(std::size_t width) : width_(width)
{
	if (width == 0) throw std::invalid_argument("RowSpill: width must be > 0");
	block_.reserve(kBlockRows * width_);
}

RowSpill::~RowSpill()
{
	if (fd_ >= 0) ::close(fd_);
}

RowSpill::RowSpill(RowSpill&& o) noexcept
	: width_(o.width_), rows_(o.rows_), file_rows_(o.file_rows_), block_(std::move(o.block_)), fd_(o.fd_), dir_(std::move(o.dir_))
{
	o.fd_ = -1;
	o.rows_ = o.file_rows_ = 0;
}

RowSpill& RowSpill::operator=(RowSpill&& o) noexcept
{
	if (this != &o)
	{
		if (fd_ >= 0) ::close(fd_);
		width_ = o.width_;
		rows_ = o.rows_;
		file_rows_ = o.file_rows_;
		block_ = std::move(o.block_);
		fd_ = o.fd_;
		dir_ = std::move(o.dir_);
		o.fd_ = -1;
		o.rows_ = o.file_rows_ = 0;
	}
	return *this;
}

void RowSpill::push(const double* row)
{
	if (block_.size() == kBlockRows * width_) flushBlock();
	block_.insert(block_.end(), row, row + width_);
	rows_++;
}

void RowSpill::flushBlock()
{
	if (fd_ < 0)
	{
		dir_ = spillDir();
		std::string name = dir_ + "/mrpt_fog_spill.XXXXXX";
		fd_ = ::mkstemp(name.data());
		if (fd_ < 0)
			throw std::runtime_error("cannot create a temporary file in " + dir_ + " (set TMPDIR): " + std::strerror(errno));
		::unlink(name.c_str());  // anonymous from now on: nothing left behind
	}
	const char* p = reinterpret_cast<const char*>(block_.data());
	std::size_t left = block_.size() * sizeof(double);
	auto off = static_cast<off_t>(file_rows_ * width_ * sizeof(double));
	while (left > 0)
	{
		const ssize_t w = ::pwrite(fd_, p, left, off);
		if (w < 0 && errno == EINTR) continue;
		if (w <= 0)
			throw std::runtime_error("cannot write the temporary file in " + dir_ + " (" +
									 std::to_string(file_rows_ * width_ * sizeof(double) >> 20) +
									 " MB written; set TMPDIR to a larger file system): " + std::strerror(errno));
		p += w;
		left -= static_cast<std::size_t>(w);
		off += w;
	}
	file_rows_ += block_.size() / width_;
	block_.clear();
}

void RowSpill::readFileRows(double* to, std::size_t first_row, std::size_t n) const
{
	char* p = reinterpret_cast<char*>(to);
	std::size_t left = n * width_ * sizeof(double);
	auto off = static_cast<off_t>(first_row * width_ * sizeof(double));
	while (left > 0)
	{
		const ssize_t r = ::pread(fd_, p, left, off);
		if (r < 0 && errno == EINTR) continue;
		if (r <= 0)
			throw std::runtime_error("cannot read back the temporary file in " + dir_ + ": " +
									 (r == 0 ? std::string("it is shorter than written") : std::strerror(errno)));
		p += r;
		left -= static_cast<std::size_t>(r);
		off += r;
	}
}

void RowSpill::forEachBlock(const std::function<void(const double*, std::size_t, std::size_t)>& f) const
{
	if (file_rows_ > 0)
	{
		std::vector<double> buf(kBlockRows * width_);
		for (std::size_t r0 = 0; r0 < file_rows_; r0 += kBlockRows)
		{
			const std::size_t n = std::min(kBlockRows, file_rows_ - r0);
			readFileRows(buf.data(), r0, n);
			f(buf.data(), n, r0);
		}
	}
	if (!block_.empty()) f(block_.data(), block_.size() / width_, file_rows_);
}

RowSpill::Reader::Reader(const RowSpill& s) : s_(s) {}

const double* RowSpill::Reader::next()
{
	if (pos_ >= s_.rows_) return nullptr;
	if (pos_ >= block_first_ + block_rows_)
	{
		block_first_ = pos_;
		if (pos_ < s_.file_rows_)
		{
			block_rows_ = std::min(kBlockRows, s_.file_rows_ - pos_);
			buf_.resize(kBlockRows * s_.width_);
			s_.readFileRows(buf_.data(), pos_, block_rows_);
			block_ = buf_.data();
		}
		else
		{
			block_rows_ = s_.rows_ - s_.file_rows_;
			block_ = s_.block_.data();
		}
	}
	return block_ + (pos_++ - block_first_) * s_.width_;
}

}  // namespace mrpt_fog
