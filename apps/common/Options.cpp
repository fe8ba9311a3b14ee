/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "Options.h"

#include <mrpt_fog/common/OutputSafety.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace mrpt_fog::app
{
namespace
{
std::string number(double v)
{
	if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.10g", v);
	return buf;
}

std::string optionName(const TCLAP::Arg& a) { return a.getFlag().empty() ? "--" + a.getName() : "-" + a.getFlag(); }

std::string withRangeText(const std::string& help, const std::string& unit, const detail::NumberCheck& c)
{
	return help + " (unit: " + unit + "; accepts " + c.description() + ")";
}

/** Whole number as the user wrote it: optional '+', then digits only. */
bool parseWhole(const std::string& text, std::uint64_t& v)
{
	const char* b = text.data();
	const char* e = b + text.size();
	if (b != e && *b == '+') b++;
	if (b == e || !std::all_of(b, e, [](char c) { return c >= '0' && c <= '9'; })) return false;
	const auto r = std::from_chars(b, e, v);
	return r.ec == std::errc() && r.ptr == e;
}

struct Registered
{
	const TCLAP::Arg* arg;
	detail::FileRole role;
	std::function<std::vector<std::string>()> paths;
	const detail::FileRegistration* owner;
};
std::vector<Registered>& registry()
{
	static std::vector<Registered> r;
	return r;
}
}  // namespace

std::string Range::text() const
{
	return std::string(lo_open ? "(" : "[") + number(lo) + ", " + number(hi) + (hi_open ? ")" : "]");
}

namespace detail
{
std::string NumberCheck::description() const
{
	return (kind_ == Kind::Count ? "a whole number in " : "a number in ") + range_.text();
}

bool NumberCheck::check(const std::string& text) const
{
	const auto refuse = [&](const std::string& why) {
		throw TCLAP::CmdLineParseException("--" + name_ + " '" + text + "': " + why, "--" + name_);
	};
	if (kind_ == Kind::Count)
	{
		std::uint64_t v = 0;
		if (!parseWhole(text, v))
		{
			const bool digits_too_many = !text.empty() && text.find_first_not_of("+0123456789") == std::string::npos;
			refuse(digits_too_many ? "too large; must be " + description()
								   : "not a whole number; must be " + description());
		}
		if (!range_.contains(static_cast<double>(v))) refuse("out of range; must be " + description());
		return true;
	}
	const char* b = text.c_str();
	char* end = nullptr;
	errno = 0;
	const double v = std::strtod(b, &end);
	if (text.empty() || end == b || *end != '\0') refuse("not a number; must be " + description());
	if (!std::isfinite(v)) refuse("not a finite number; must be " + description());
	if (!range_.contains(v)) refuse("out of range; must be " + description());
	return true;
}

double NumberCheck::parse(const std::string& text) const
{
	if (kind_ == Kind::Count)
	{
		std::uint64_t v = 0;
		parseWhole(text, v);
		return static_cast<double>(v);
	}
	return std::strtod(text.c_str(), nullptr);
}

FileRegistration::FileRegistration(const TCLAP::Arg& arg, std::string& description, FileRole role,
								   std::function<std::vector<std::string>()> paths)
{
	description += role == FileRole::Input	  ? " (file read)"
				   : role == FileRole::Output ? " (file written)"
											  : " (folder written into)";
	registry().push_back({&arg, role, std::move(paths), this});
}

FileRegistration::~FileRegistration()
{
	auto& r = registry();
	r.erase(std::remove_if(r.begin(), r.end(), [this](const Registered& x) { return x.owner == this; }), r.end());
}
}  // namespace detail

RealArg::RealArg(TCLAP::CmdLine& cmd, const std::string& name, const std::string& help, const std::string& unit,
				 Range range, double default_value, const std::string& type_desc)
	: check_(name, type_desc, detail::NumberCheck::Kind::Real, range),
	  default_(default_value),
	  arg_("", name, withRangeText(help, unit, check_), false, number(default_value), &check_, cmd)
{
	if (!std::isnan(default_value) && !range.contains(default_value))
		throw std::logic_error("--" + name + ": default " + number(default_value) + " outside " + range.text());
}

double RealArg::getValue() const { return arg_.isSet() ? check_.parse(arg_.getValue()) : default_; }

CountArg::CountArg(TCLAP::CmdLine& cmd, const std::string& name, const std::string& help, const std::string& unit,
				   std::uint64_t lo, std::uint64_t hi, std::uint64_t default_value, const std::string& type_desc)
	: check_(name, type_desc, detail::NumberCheck::Kind::Count,
			 Range::closed(static_cast<double>(lo), static_cast<double>(hi))),
	  default_(default_value),
	  arg_("", name, withRangeText(help, unit, check_), false, std::to_string(default_value), &check_, cmd)
{
	if (default_value < lo || default_value > hi)
		throw std::logic_error("--" + name + ": default " + std::to_string(default_value) + " outside " +
							   check_.range().text());
}

std::uint64_t CountArg::getValue() const
{
	if (!arg_.isSet()) return default_;
	std::uint64_t v = 0;
	parseWhole(arg_.getValue(), v);
	return v;
}

void checkDeclaredFiles()
{
	std::vector<FileArg> inputs, outputs;
	std::vector<FileArg> dirs;
	for (const auto& r : registry())
	{
		for (const auto& p : r.paths())
		{
			if (p.empty()) continue;
			const FileArg f{optionName(*r.arg), p};
			switch (r.role)
			{
				case detail::FileRole::Input:
					inputs.push_back(f);
					break;
				case detail::FileRole::Output:
					outputs.push_back(f);
					break;
				case detail::FileRole::OutputDir:
					dirs.push_back(f);
					break;
			}
		}
	}
	requireSafeOutputs(inputs, outputs);
	for (std::size_t i = 0; i < dirs.size(); i++)
	{
		const FileArg& d = dirs[i];
		struct stat st{};
		if (::stat(d.path.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
		{
			for (const auto& in : inputs)
				if (sameExistingFile(in.path, d.path))
					throw std::invalid_argument(d.option + " '" + d.path + "' is the input " + in.option + " '" +
												in.path + "', not a directory: refusing to write there");
			throw std::invalid_argument(d.option + " '" + d.path + "' exists and is not a directory");
		}
		for (const auto& o : outputs)
			if (o.path == d.path || sameExistingFile(o.path, d.path))
				throw std::invalid_argument(d.option + " '" + d.path + "' is also the output " + o.option +
											": two outputs cannot share a path");
		for (std::size_t j = 0; j < i; j++)
			if (dirs[j].path == d.path || sameExistingFile(dirs[j].path, d.path))
				throw std::invalid_argument(d.option + " '" + d.path + "' is also the output " + dirs[j].option +
											": two outputs cannot share a path");
	}
}

}  // namespace mrpt_fog::app
