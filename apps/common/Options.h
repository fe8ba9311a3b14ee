/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Options.h
 * The option layer every program declares its numeric and file options with.
 *
 * Numeric options are declared once with their unit and accepted range; the text is checked while
 * the command line is parsed, before anything is converted or read: a count must be written as a
 * whole number ("-1" is refused, never wrapped to 2^32), a real must be finite (nan, inf, 1e999
 * and trailing text are refused), and both must lie in the range. A refusal is one line naming
 * the option, exit 2 (as every usage error):
 *
 *   app::CountArg particles(cmd, "particles", "particles per filter", "particles", 10, 100000, 300);
 *   app::RealArg window(cmd, "window", "rate window", "s", app::Range::closed(1, 86400), 60);
 *   app::RealArg lat(cmd, "latitude-deg", "latitude (default: the drive's)", "deg", app::Range::closed(-90, 90));
 *   ... app::parseCommandLine(cmd, ...) ...
 *   particles.get<unsigned>(), window.getValue(), lat.isSet()
 *
 * --help shows each after its description as "(unit: s; accepts a number in [1, 86400])"; the
 * option test reads that line back, so keep the layer's wording.
 *
 * File options are declared with their role; parseCommandLine() then checks every declared
 * output against every declared input and every other output (mrpt_fog/common/OutputSafety.h)
 * before the program does any work, so that no output option can skip the check:
 *
 *   app::InputArg in("i", "input", "FOG log", true, "", "IN", cmd);
 *   app::InputMultiArg runs("i", "input", "runs", true, "RUN", cmd);
 *   app::OutputArg json("", "json", "write the figures as JSON", false, "", "FILE", cmd);
 *   app::OutputDirArg plots("", "plots", "write the PNGs here", false, "", "DIR", cmd);
 *
 * (same constructor arguments as TCLAP::ValueArg / MultiArg<std::string>). */

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog::app
{
/** The values a real option accepts: an interval, each end open or closed (infinite ends open). */
struct Range
{
	double lo = -std::numeric_limits<double>::infinity();
	double hi = std::numeric_limits<double>::infinity();
	bool lo_open = true, hi_open = true;

	static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
	/** (lo, hi] */
	static Range aboveUpTo(double lo, double hi) { return {lo, hi, true, false}; }
	static Range open(double lo, double hi) { return {lo, hi, true, true}; }
	bool contains(double v) const
	{
		return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
	}
	/** "[0, 3600]", "(0, 0.5)", "[-90, 90]" */
	std::string text() const;
};

namespace detail
{
/** Checks an option's text as TCLAP reads it; throws TCLAP::CmdLineParseException naming the
 * option. */
class NumberCheck : public TCLAP::Constraint<std::string>
{
   public:
	enum class Kind
	{
		Real,
		Count
	};
	NumberCheck(std::string name, std::string type_desc, Kind kind, Range range)
		: name_(std::move(name)), type_desc_(std::move(type_desc)), kind_(kind), range_(range)
	{
	}
	std::string description() const override;
	std::string shortID() const override { return type_desc_; }
	bool check(const std::string& text) const override;  // throws on refusal
	/** The value of accepted text (check() first). */
	double parse(const std::string& text) const;
	const Range& range() const { return range_; }

   private:
	std::string name_, type_desc_;
	Kind kind_;
	Range range_;
};

/** A declared file option (see InputArg, OutputArg); registered while it lives. */
enum class FileRole
{
	Input,
	Output,
	OutputDir
};
class FileRegistration
{
   public:
	/** Appends the role to the option's help ("(file read)", "(file written)", "(folder written
	 * into)": the output test reads it back). */
	FileRegistration(const TCLAP::Arg& arg, std::string& description, FileRole role,
					 std::function<std::vector<std::string>()> paths);
	~FileRegistration();
	FileRegistration(const FileRegistration&) = delete;
	FileRegistration& operator=(const FileRegistration&) = delete;
};
}  // namespace detail

/** A real-valued option with a unit and a range (see the file comment). Without a default
 * value (NaN) it has none: test isSet(). */
class RealArg
{
   public:
	RealArg(TCLAP::CmdLine& cmd, const std::string& name, const std::string& help, const std::string& unit,
			Range range, double default_value = std::numeric_limits<double>::quiet_NaN(),
			const std::string& type_desc = "X");
	double getValue() const;
	bool isSet() const { return arg_.isSet(); }

   private:
	detail::NumberCheck check_;
	double default_;
	mutable TCLAP::ValueArg<std::string> arg_;  // TCLAP's getValue() is not const
};

/** A whole-number option (a count, a seed, an order) in [lo, hi] (see the file comment). */
class CountArg
{
   public:
	CountArg(TCLAP::CmdLine& cmd, const std::string& name, const std::string& help, const std::string& unit,
			 std::uint64_t lo, std::uint64_t hi, std::uint64_t default_value, const std::string& type_desc = "N");
	std::uint64_t getValue() const;
	/** The value as T; std::logic_error when the declared range does not fit T. */
	template <class T>
	T get() const
	{
		if (check_.range().hi > static_cast<double>(std::numeric_limits<T>::max()))
			throw std::logic_error("option range does not fit its type");
		return static_cast<T>(getValue());
	}
	bool isSet() const { return arg_.isSet(); }

   private:
	detail::NumberCheck check_;
	std::uint64_t default_;
	mutable TCLAP::ValueArg<std::string> arg_;  // TCLAP's getValue() is not const
};

/** A file the program reads. */
class InputArg : public TCLAP::ValueArg<std::string>
{
   public:
	using TCLAP::ValueArg<std::string>::ValueArg;

   private:
	detail::FileRegistration reg_{*this, _description, detail::FileRole::Input, [this] { return std::vector<std::string>{getValue()}; }};
};

/** Files the program reads, the option repeated. */
class InputMultiArg : public TCLAP::MultiArg<std::string>
{
   public:
	using TCLAP::MultiArg<std::string>::MultiArg;

   private:
	detail::FileRegistration reg_{*this, _description, detail::FileRole::Input, [this] { return getValue(); }};
};

/** A file the program writes. */
class OutputArg : public TCLAP::ValueArg<std::string>
{
   public:
	using TCLAP::ValueArg<std::string>::ValueArg;

   private:
	detail::FileRegistration reg_{*this, _description, detail::FileRole::Output, [this] { return std::vector<std::string>{getValue()}; }};
};

/** A directory the program writes files into (created when missing): refused when it names an
 * existing file that is not a directory, or the same path as another output. */
class OutputDirArg : public TCLAP::ValueArg<std::string>
{
   public:
	using TCLAP::ValueArg<std::string>::ValueArg;

   private:
	detail::FileRegistration reg_{*this, _description, detail::FileRole::OutputDir,
								  [this] { return std::vector<std::string>{getValue()}; }};
};

/** Runs the output rule on every file option declared so far (called by parseCommandLine after
 * a successful parse): throws std::invalid_argument naming the options and paths. */
void checkDeclaredFiles();

}  // namespace mrpt_fog::app
