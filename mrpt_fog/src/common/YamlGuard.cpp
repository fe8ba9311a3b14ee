/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/Utf8.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace mrpt_fog
{
namespace
{
[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& what)
{
	throw std::invalid_argument(source + ":" + std::to_string(line) + ": " + what);
}
}  // namespace

void requireSafeYamlText(const std::string& text, const std::string& source, const YamlLimits& limits)
{
	if (text.size() > limits.max_bytes)
		throw std::invalid_argument(source + ": YAML text of " + std::to_string(text.size()) + " bytes exceeds the limit of " +
									std::to_string(limits.max_bytes) + " bytes");
	if (const std::size_t bad = firstInvalidUtf8(text); bad != std::string::npos)
		throw std::invalid_argument(source + ": not valid UTF-8 text (byte offset " + std::to_string(bad) + ")");

	std::vector<std::size_t> indents;  // block indentation levels open at this point
	std::size_t flow = 0;  // open '[' / '{'
	char quote = 0;  // inside a quoted scalar (may span lines)
	std::size_t line_no = 0;
	std::size_t pos = 0;
	const auto tooDeep = [&](std::size_t depth) {
		if (depth > limits.max_depth)
			fail(source, line_no, "YAML nesting depth exceeds the limit of " + std::to_string(limits.max_depth) + " levels");
	};
	while (pos < text.size())
	{
		line_no++;
		std::size_t end = text.find('\n', pos);
		if (end == std::string::npos) end = text.size();
		std::size_t i = pos;
		if (!quote && flow == 0)
		{
			std::size_t indent = 0;
			while (i < end && text[i] == ' ') i++, indent++;
			const bool blank = i == end || text[i] == '#' || text[i] == '\r';
			if (!blank)
			{
				while (!indents.empty() && indents.back() > indent) indents.pop_back();
				if (indents.empty() || indents.back() < indent) indents.push_back(indent);
				std::size_t inline_depth = 0;
				std::size_t j = i;
				while (j + 1 < end && text[j] == '-' && (text[j + 1] == ' ' || text[j + 1] == '\t'))
				{
					inline_depth++;
					j += 2;
					while (j < end && (text[j] == ' ' || text[j] == '\t')) j++;
				}
				tooDeep(indents.size() + inline_depth + 1);
			}
		}
		bool token_start = true;  // at the start of a token (after blank, '[', '{', ',', ':')
		for (; i < end; i++)
		{
			const char c = text[i];
			if (quote)
			{
				if (quote == '"' && c == '\\') i++;
				else if (c == quote)
				{
					if (quote == '\'' && i + 1 < end && text[i + 1] == '\'') i++;  // '' escape
					else quote = 0;
				}
				continue;
			}
			if (c == '#' && token_start) break;  // comment
			if ((c == '"' || c == '\'') && token_start)
			{
				quote = c;
				continue;
			}
			if (c == '*' && token_start)
				fail(source, line_no, "YAML aliases (*name) are not accepted in this file");
			if (c == '[' || c == '{')
			{
				flow++;
				tooDeep(indents.size() + flow + 1);
			}
			else if ((c == ']' || c == '}') && flow > 0)
				flow--;
			token_start = c == ' ' || c == '\t' || c == '[' || c == '{' || c == ',' || c == ':' || c == '-' || c == '?';
		}
		pos = end + 1;
	}
}

std::string readYamlTextLimited(const std::string& path, const YamlLimits& limits)
{
	struct stat st{};
	if (::stat(path.c_str(), &st) != 0)
		throw std::invalid_argument(path + ": cannot open: " + std::strerror(errno));
	if (S_ISDIR(st.st_mode)) throw std::invalid_argument(path + ": is a directory, not a YAML file");
	if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > limits.max_bytes)
		throw std::invalid_argument(path + ": file of " + std::to_string(st.st_size) + " bytes exceeds the limit of " +
									std::to_string(limits.max_bytes) + " bytes for a YAML file");
	std::ifstream f(path, std::ios::binary);
	if (!f) throw std::invalid_argument(path + ": cannot open: " + std::strerror(errno));
	std::string text;
	std::vector<char> buf(1 << 16);
	while (f)
	{
		f.read(buf.data(), static_cast<std::streamsize>(buf.size()));
		text.append(buf.data(), static_cast<std::size_t>(f.gcount()));
		if (text.size() > limits.max_bytes)  // a FIFO or a growing file
			throw std::invalid_argument(path + ": more than the limit of " + std::to_string(limits.max_bytes) +
										" bytes for a YAML file");
	}
	if (f.bad()) throw std::invalid_argument(path + ": read error");
	requireSafeYamlText(text, path, limits);
	return text;
}

}  // namespace mrpt_fog
