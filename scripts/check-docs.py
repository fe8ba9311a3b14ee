#!/usr/bin/env python3
"""Checks the user documentation (README.md, CHANGELOG.md, docs/):

1. every relative link in README.md and docs/**/*.md resolves to a file (and a heading anchor,
   when one is given, to a heading of that file);
2. the user docs (README.md and docs/ outside docs/validation/) hold no date (YYYY-MM-DD) and no
   commit id of this repository (a 7..40-digit hex word that git resolves to a commit);
3. README.md has at most 150 lines and its first command (a fenced code block) starts within
   its first 40 lines.

Usage: scripts/check-docs.py [repo root]. Prints one line per problem; exit 1 if any."""
import os
import re
import subprocess
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
problems = []


def md_files():
    out = [os.path.join(root, "README.md")]
    if os.path.exists(os.path.join(root, "CHANGELOG.md")):
        out.append(os.path.join(root, "CHANGELOG.md"))
    for d, _, files in os.walk(os.path.join(root, "docs")):
        out += [os.path.join(d, f) for f in sorted(files) if f.endswith(".md")]
    return out


def anchors(path):
    """GitHub-style heading anchors of a markdown file."""
    result = set()
    seen = {}
    in_code = False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            in_code = not in_code
        if in_code or not line.startswith("#"):
            continue
        text = line.lstrip("#").strip().lower()
        text = re.sub(r"[^\w\- ]", "", text).replace(" ", "-")
        n = seen.get(text, 0)
        seen[text] = n + 1
        result.add(text if n == 0 else f"{text}-{n}")  # repeated headings get -1, -2, ...
    return result


def strip_code(text):
    """The text without fenced code blocks and inline code (links there are not links)."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return re.sub(r"`[^`\n]*`", "", text)


link_re = re.compile(r"\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
for path in md_files():
    rel = os.path.relpath(path, root)
    text = strip_code(open(path, encoding="utf-8").read())
    for target in link_re.findall(text):
        if re.match(r"^[a-z]+:", target) or target.startswith("#") and not target[1:]:
            continue  # external (http:, mailto:)
        file_part, _, anchor = target.partition("#")
        dest = path if not file_part else os.path.normpath(os.path.join(os.path.dirname(path), file_part))
        if not os.path.exists(dest):
            problems.append(f"{rel}: broken link {target}")
        elif anchor and dest.endswith(".md") and anchor.lower() not in anchors(dest):
            problems.append(f"{rel}: link {target}: no heading '{anchor}' in {os.path.relpath(dest, root)}")


def is_commit(word):
    r = subprocess.run(["git", "-C", root, "cat-file", "-t", word], capture_output=True, text=True)
    return r.returncode == 0 and r.stdout.strip() == "commit"


date_re = re.compile(r"\b20\d\d-[01]\d-[0-3]\d\b")
hex_re = re.compile(r"\b[0-9a-f]{7,40}\b")
have_git = subprocess.run(["git", "-C", root, "rev-parse"], capture_output=True).returncode == 0
for path in md_files():
    rel = os.path.relpath(path, root)
    if rel.startswith(os.path.join("docs", "validation")) or rel == "CHANGELOG.md":
        continue
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        for d in date_re.findall(line):
            problems.append(f"{rel}:{n}: a date ({d}) in a user doc")
        if have_git:
            for h in hex_re.findall(line):
                if re.search(r"[a-f]", h) and re.search(r"\d", h) and is_commit(h):
                    problems.append(f"{rel}:{n}: a commit id ({h}) in a user doc")

readme = open(os.path.join(root, "README.md"), encoding="utf-8").read().split("\n")
if len(readme) > 151 or (len(readme) == 151 and readme[-1] != ""):
    problems.append(f"README.md: {len(readme) - (readme[-1] == '')} lines (at most 150)")
first_code = next((i + 1 for i, l in enumerate(readme) if l.startswith("```")), None)
if first_code is None or first_code >= 40:
    problems.append(f"README.md: first command at line {first_code} (must start within the first 40 lines)")

for p in problems:
    print(p)
print(f"check-docs: {len(md_files())} files, {len(problems)} problem(s)")
sys.exit(1 if problems else 0)
