/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzStream.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>

namespace mrpt_fog::io
{
namespace
{
constexpr std::size_t kChunk = 1 << 18;  // 256 KiB
}

// ------------------------------------------------------------------ GzReader

struct GzReader::Inflater
{
	z_stream s{};
	bool init = false;
	~Inflater()
	{
		if (init) inflateEnd(&s);
	}
};

GzReader::GzReader(const std::string& path) : path_(path), z_(std::make_unique<Inflater>())
{
	f_ = std::fopen(path.c_str(), "rb");
	if (!f_) throw FogIoError(path + ": cannot open: " + std::strerror(errno));
	struct stat st{};
	if (::fstat(fileno(f_), &st) == 0 && S_ISDIR(st.st_mode))
	{
		std::fclose(f_);
		f_ = nullptr;
		throw FogIoError(path + ": is a directory, not a log file");
	}
	if (::fstat(fileno(f_), &st) == 0 && S_ISREG(st.st_mode)) file_bytes_ = static_cast<std::uint64_t>(st.st_size);
	in_.resize(kChunk);
	buf_.resize(kChunk);
	in_len_ = std::fread(in_.data(), 1, in_.size(), f_);
	file_read_ = in_len_;
	if (in_len_ < in_.size()) file_eof_ = true;
	if (std::ferror(f_)) throw FogIoError(path + ": read error: " + std::strerror(errno));
	gzip_ = in_len_ >= 2 && in_[0] == 0x1f && in_[1] == 0x8b;
}

GzReader::~GzReader()
{
	if (f_) std::fclose(f_);
}

bool GzReader::fill()
{
	// Keep the bytes not yet delivered (peek() asks for more than are left), append after them.
	if (buf_pos_ > 0)
	{
		if (buf_pos_ < buf_len_) std::memmove(buf_.data(), buf_.data() + buf_pos_, buf_len_ - buf_pos_);
		buf_len_ -= buf_pos_;
		buf_pos_ = 0;
	}
	const std::size_t start = buf_len_;
	if (start == buf_.size()) return false;  // full: nothing can be appended
	for (;;)
	{
		if (in_pos_ == in_len_ && !file_eof_)
		{
			in_len_ = std::fread(in_.data(), 1, in_.size(), f_);
			in_pos_ = 0;
			file_read_ += in_len_;
			if (std::ferror(f_)) throw FogIoError(path_ + ": read error: " + std::strerror(errno));
			if (in_len_ < in_.size()) file_eof_ = true;
		}
		if (!gzip_)
		{
			if (in_pos_ == in_len_) return buf_len_ > start;
			const std::size_t n = std::min(in_len_ - in_pos_, buf_.size() - buf_len_);
			std::memcpy(buf_.data() + buf_len_, in_.data() + in_pos_, n);
			in_pos_ += n;
			buf_len_ += n;
			return true;
		}
		if (!member_open_)
		{
			if (in_pos_ == in_len_ && file_eof_) return buf_len_ > start;  // clean end after a whole member
			if (!z_->init)
			{
				if (inflateInit2(&z_->s, 15 + 16) != Z_OK) throw FogIoError(path_ + ": cannot start gzip decompression");
				z_->init = true;
			}
			else if (inflateReset(&z_->s) != Z_OK)
				throw FogIoError(path_ + ": cannot restart gzip decompression");
			member_open_ = true;
			members_++;
		}
		if (in_pos_ == in_len_ && file_eof_)
			throw FogIoError(path_ + ": truncated or corrupt gzip file: it ends inside member " + std::to_string(members_) + " after " +
							 std::to_string(out_pos_ + buf_len_) + " decompressed bytes (" + std::to_string(file_read_) +
							 " compressed bytes)");
		z_->s.next_in = in_.data() + in_pos_;
		z_->s.avail_in = static_cast<uInt>(in_len_ - in_pos_);
		z_->s.next_out = buf_.data() + buf_len_;
		z_->s.avail_out = static_cast<uInt>(buf_.size() - buf_len_);
		const int rc = inflate(&z_->s, Z_NO_FLUSH);
		in_pos_ = in_len_ - z_->s.avail_in;
		buf_len_ = buf_.size() - z_->s.avail_out;
		if (rc == Z_STREAM_END)
		{
			member_open_ = false;
			// Padding of zeros after the last member (some tools) ends the data.
			while (in_pos_ < in_len_ && in_[in_pos_] == 0) in_pos_++;
			if (buf_len_ > start) return true;
			continue;
		}
		if (rc == Z_BUF_ERROR && z_->s.avail_in == 0) continue;  // needs more input
		if (rc != Z_OK)
			throw FogIoError(path_ + ": corrupt gzip data in member " + std::to_string(members_) + " after " +
							 std::to_string(out_pos_ + buf_len_) + " decompressed bytes" +
							 (rc == Z_DATA_ERROR && z_->s.msg ? std::string(" (") + z_->s.msg + ")" : std::string()) +
							 " (truncated or corrupt gzip file)");
		if (buf_len_ == buf_.size()) return true;
	}
}

std::size_t GzReader::peek(const unsigned char*& p, std::size_t want)
{
	want = std::min(want, buf_.size());
	while (buf_len_ - buf_pos_ < want)
		if (!fill()) break;
	p = buf_.data() + buf_pos_;
	return buf_len_ - buf_pos_;
}

void GzReader::consume(std::size_t n)
{
	n = std::min(n, buf_len_ - buf_pos_);
	buf_pos_ += n;
	out_pos_ += n;
}

size_t GzReader::Read(void* buffer, size_t count)
{
	if (count <= buf_len_ - buf_pos_)  // fast path: MRPT's archive reads field by field
	{
		std::memcpy(buffer, buf_.data() + buf_pos_, count);
		buf_pos_ += count;
		out_pos_ += count;
		return count;
	}
	auto* out = static_cast<unsigned char*>(buffer);
	std::size_t done = 0;
	while (done < count)
	{
		if (buf_pos_ == buf_len_ && !fill()) break;
		const std::size_t n = std::min(count - done, buf_len_ - buf_pos_);
		std::memcpy(out + done, buf_.data() + buf_pos_, n);
		buf_pos_ += n;
		done += n;
	}
	out_pos_ += done;
	return done;
}

bool GzReader::atEnd() { return buf_pos_ == buf_len_ && !fill(); }

bool GzReader::readLine(std::string& line, std::size_t max_bytes)
{
	line.clear();
	if (atEnd()) return false;
	line_no_++;
	for (;;)
	{
		if (buf_pos_ == buf_len_ && !fill()) break;
		const unsigned char* b = buf_.data() + buf_pos_;
		const std::size_t avail = buf_len_ - buf_pos_;
		const void* nl = std::memchr(b, '\n', avail);
		const std::size_t n = nl ? static_cast<std::size_t>(static_cast<const unsigned char*>(nl) - b) : avail;
		if (line.size() + n > max_bytes)
			throw FogIoError(path_ + ":" + std::to_string(line_no_) + ": line longer than the limit of " +
							 std::to_string(max_bytes) + " bytes");
		line.append(reinterpret_cast<const char*>(b), n);
		buf_pos_ += n + (nl ? 1 : 0);
		out_pos_ += n + (nl ? 1 : 0);
		if (nl) break;
	}
	if (!line.empty() && line.back() == '\r') line.pop_back();
	return true;
}

size_t GzReader::Write(const void*, size_t) { throw FogIoError(path_ + ": GzReader cannot write"); }
uint64_t GzReader::Seek(int64_t, CStream::TSeekOrigin) { throw FogIoError(path_ + ": GzReader cannot seek"); }

// ------------------------------------------------------------------ GzWriter

struct GzWriter::Deflater
{
	z_stream s{};
	bool init = false;
	~Deflater()
	{
		if (init) deflateEnd(&s);
	}
};

GzWriter::GzWriter(const std::string& path, bool compress, int level, const std::string& name)
	: path_(path), name_(name.empty() ? path : name), compress_(compress), z_(std::make_unique<Deflater>())
{
	f_ = std::fopen(path.c_str(), "wb");
	if (!f_) fail("cannot create", errno);
	buf_.resize(kChunk);
	if (compress_)
	{
		out_.resize(kChunk);
		if (deflateInit2(&z_->s, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
			fail("cannot start gzip compression", 0);
		z_->init = true;
	}
}

GzWriter::~GzWriter()
{
	if (f_) std::fclose(f_);
}

void GzWriter::fail(const std::string& what, int err)
{
	throw FogIoError(name_ + ": " + what + (err ? std::string(": ") + std::strerror(err) : std::string()));
}

void GzWriter::writeRaw(const unsigned char* p, std::size_t n)
{
	if (n == 0) return;
	errno = 0;
	if (std::fwrite(p, 1, n, f_) != n) fail("write error", errno ? errno : EIO);
}

void GzWriter::flushBuffer(bool finish)
{
	if (!compress_)
	{
		writeRaw(buf_.data(), buf_len_);
		buf_len_ = 0;
		return;
	}
	z_->s.next_in = buf_.data();
	z_->s.avail_in = static_cast<uInt>(buf_len_);
	for (;;)
	{
		z_->s.next_out = out_.data();
		z_->s.avail_out = static_cast<uInt>(out_.size());
		const int rc = deflate(&z_->s, finish ? Z_FINISH : Z_NO_FLUSH);
		if (rc == Z_STREAM_ERROR) fail("gzip compression failed", 0);
		writeRaw(out_.data(), out_.size() - z_->s.avail_out);
		if (finish ? rc == Z_STREAM_END : z_->s.avail_in == 0 && z_->s.avail_out != 0) break;
	}
	buf_len_ = 0;
}

size_t GzWriter::Write(const void* buffer, size_t count)
{
	if (count < buf_.size() - buf_len_ && !closed_)  // fast path: MRPT's archive writes field by field
	{
		std::memcpy(buf_.data() + buf_len_, buffer, count);
		buf_len_ += count;
		in_bytes_ += count;
		return count;
	}
	if (closed_) fail("write after close", 0);
	const auto* p = static_cast<const unsigned char*>(buffer);
	const size_t total = count;
	in_bytes_ += count;
	while (count > 0)
	{
		const std::size_t n = std::min(count, buf_.size() - buf_len_);
		std::memcpy(buf_.data() + buf_len_, p, n);
		buf_len_ += n;
		p += n;
		count -= n;
		if (buf_len_ == buf_.size()) flushBuffer(false);
	}
	return total;
}

void GzWriter::close()
{
	if (closed_) return;
	closed_ = true;
	flushBuffer(true);
	errno = 0;
	if (std::fflush(f_) != 0) fail("write error", errno ? errno : EIO);
	std::FILE* f = f_;
	f_ = nullptr;
	if (std::fclose(f) != 0) fail("write error (on close)", errno ? errno : EIO);
}

size_t GzWriter::Read(void*, size_t) { throw FogIoError(name_ + ": GzWriter cannot read"); }
uint64_t GzWriter::Seek(int64_t, CStream::TSeekOrigin) { throw FogIoError(name_ + ": GzWriter cannot seek"); }

}  // namespace mrpt_fog::io
