#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The documentation test: the README and the manual say what the code does.

Checks, over the files git tracks or would track (untracked files that are not ignored count):
  links     every relative link and image in every .md file resolves, anchors included;
  citations every repository path a source file's comments name (docs/..., scripts/..., tests/..., ...)
            and every markdown document it names by its file name exists;
  worklog   no file keeps a work log: no numbered stops, issues or items of the work;
  readme    README.md is at most 20 KB;
  version   the newest version in CHANGELOG.md is the CMake project's version;
  commands  every line starting with `scadray ` in a ```sh block of README.md and docs/ runs
            and exits 0; the lines of one block run in order in one scratch folder where the
            repository's scenes/ and tests/ are visible under those names (--scadray names the
            binary; without it, commands are not run).

Usage: scripts/check_docs.py [--scadray BINARY] [--only CHECK,...] [--list]
Exit 0 when everything passes, 1 on any failure, 77 when commands were skipped because a
program they need (povray, openscad, ffmpeg) is not installed and nothing failed.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unicodedata

ROOT = os.path.realpath(os.path.join(os.path.dirname(__file__), ".."))
README_LIMIT = 20 * 1024
# Top-level folders whose paths a comment may cite
TOP_DIRS = ("docs", "scripts", "tests", "core", "importers", "exporters", "tools", "cmake",
            "scenes", ".ci")
SOURCE_EXT = (".cpp", ".h", ".hpp", ".sh", ".py", ".cmake", ".scad", ".js", ".supp", ".txt",
              ".dict")
COMMAND_TIMEOUT_S = 600


def tracked_files():
    """The repository's files: git's list, or (outside a git checkout) every file but builds."""
    try:
        out = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT,
                             check=True, capture_output=True).stdout.decode()
        names = out.split("\0")
    except (OSError, subprocess.CalledProcessError):
        names = []
        for d, subdirs, fs in os.walk(ROOT):
            subdirs[:] = [s for s in subdirs if not s.startswith((".git", "build", "out"))]
            names += [os.path.relpath(os.path.join(d, f), ROOT) for f in fs]
    return sorted(f for f in names if f and os.path.isfile(os.path.join(ROOT, f)))


def read_text(rel):
    try:
        with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
            return f.read()
    except (UnicodeDecodeError, OSError):
        return None


def strip_code(md):
    """The markdown with fenced blocks and inline code blanked (line numbers kept)."""
    out, fenced = [], False
    for line in md.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else re.sub(r"`[^`]*`", "``", line))
    return "\n".join(out)


def slug(heading):
    """GitHub's anchor of a heading: lowercase, punctuation dropped, spaces to '-'."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links keep their text
    text = text.strip().lower()
    kept = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in " -_" or cat[0] in "LN":
            kept.append("-" if ch == " " else ch)
    return "".join(kept)


def anchors(md):
    found, counts = set(), {}
    for line in strip_code_keep_headings(md):
        m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        base = slug(m.group(2))
        n = counts.get(base, 0)
        counts[base] = n + 1
        found.add(base if n == 0 else f"{base}-{n}")
    for m in re.finditer(r'<a\s+(?:name|id)="([^"]+)"', md):
        found.add(m.group(1))
    return found


def strip_code_keep_headings(md):
    fenced = False
    for line in md.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield line.replace("`", "")


def check_links(files, fail):
    mds = [f for f in files if f.endswith(".md")]
    cache = {}
    for rel in mds:
        md = read_text(rel)
        if md is None:
            continue
        body = strip_code(md)
        targets = []
        for n, line in enumerate(body.split("\n"), 1):
            for m in re.finditer(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)", line):
                targets.append((n, m.group(1)))
            m = re.match(r"^\s*\[[^\]]+\]:\s*(\S+)", line)
            if m:
                targets.append((n, m.group(1)))
        for n, target in targets:
            target = target.strip('"')
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):
                continue  # http:, https:, mailto:
            path, _, anchor = target.partition("#")
            where = f"{rel}:{n}"
            if path:
                full = os.path.normpath(os.path.join(ROOT, os.path.dirname(rel), path))
                if not full.startswith(ROOT + os.sep) and full != ROOT:
                    fail("links", where, f"'{target}' leads outside the repository")
                    continue
                if not os.path.exists(full):
                    fail("links", where, f"'{target}' does not exist")
                    continue
            else:
                full = os.path.join(ROOT, rel)
            if anchor and full.endswith(".md"):
                if full not in cache:
                    with open(full, encoding="utf-8") as f:
                        cache[full] = anchors(f.read())
                if anchor not in cache[full]:
                    fail("links", where, f"'{target}': no heading with anchor '#{anchor}'")


def comment_of(line, c_like):
    """The comment part of a source line ("" when it has none): what follows // or a leading
    * in C-like files, what follows a # that starts a word elsewhere."""
    if c_like:
        stripped = line.lstrip()
        if stripped.startswith(("*", "/*")):
            return stripped
        i = line.find("//")
        return line[i:] if i >= 0 else ""
    m = re.search(r"(?:^|\s)#", line)
    return line[m.end():] if m else ""


def check_citations(files, fail):
    basenames = {os.path.basename(f) for f in files}
    path_re = re.compile(r"(?<![\w./$-])((?:%s)/[\w./+-]*[\w/])" %
                         "|".join(re.escape(d) for d in TOP_DIRS))
    doc_re = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")
    for rel in files:
        if not (rel.endswith(SOURCE_EXT) or os.path.basename(rel) in ("CMakeLists.txt",
                                                                        ".clang-format")):
            continue
        if rel.startswith("tests/data/") or rel.startswith("tests/fuzz/seeds/"):
            continue
        text = read_text(rel)
        if text is None:
            continue
        c_like = rel.endswith((".cpp", ".h", ".hpp", ".js", ".scad"))
        for n, line in enumerate(text.split("\n"), 1):
            line = comment_of(line, c_like)
            for m in path_re.finditer(line):
                p = m.group(1)
                rest = line[m.end():]
                if rest.startswith(("*", "{", "<", "$", "%")):
                    continue  # a pattern or a generated name
                if "*" in p or "//" in p:
                    continue
                if not os.path.exists(os.path.join(ROOT, p.rstrip("/"))):
                    fail("citations", f"{rel}:{n}", f"names '{p}', which does not exist")
            for m in re.finditer(r"(?<![\w.])\.\./[\w./-]+", line):
                full = os.path.normpath(os.path.join(ROOT, os.path.dirname(rel), m.group(0)))
                if not full.startswith(ROOT + os.sep):
                    fail("citations", f"{rel}:{n}",
                         f"names '{m.group(0)}', outside the repository")
            for m in doc_re.finditer(line):
                if m.group(1) not in basenames:
                    fail("citations", f"{rel}:{n}", f"names '{m.group(1)}', which no file is")


WORKLOG_RE = re.compile(r"\b(?:stop|issue|item)s? #?\d+\b", re.I)


def check_worklog(files, fail):
    for rel in files:
        if rel.startswith("tests/data/") or rel.startswith("tests/fuzz/seeds/"):
            continue
        text = read_text(rel)
        if text is None:
            continue
        for n, line in enumerate(text.split("\n"), 1):
            for m in WORKLOG_RE.finditer(line):
                if "/issues/" in line:  # a link to another project's tracker
                    continue
                fail("worklog", f"{rel}:{n}", f"work-log reference '{m.group(0)}'")


def check_readme(fail):
    size = os.path.getsize(os.path.join(ROOT, "README.md"))
    if size > README_LIMIT:
        fail("readme", "README.md", f"{size} bytes, more than {README_LIMIT}")


def check_version(fail):
    cmake = read_text("CMakeLists.txt")
    m = re.search(r"project\(\s*scadray\s+VERSION\s+([\d.]+)", cmake)
    changelog = read_text("CHANGELOG.md")
    c = re.search(r"^## \[([\d.]+)\]", changelog, re.M)
    if not m or not c:
        fail("version", "CHANGELOG.md", "no version in CMakeLists.txt or CHANGELOG.md")
    elif m.group(1) != c.group(1):
        fail("version", "CHANGELOG.md",
             f"newest version {c.group(1)}, but CMakeLists.txt says {m.group(1)}")


def doc_commands(files):
    """(file, line, command, block) for every `scadray ` line in a ```sh block; block numbers
    the blocks, so the commands of one block can share a folder."""
    found = []
    block = 0
    for rel in files:
        if not rel.endswith(".md") or not (rel == "README.md" or rel.startswith("docs/")):
            continue
        lines = read_text(rel).split("\n")
        fence = None
        i = 0
        while i < len(lines):
            line = lines[i]
            stripped = line.strip()
            if stripped.startswith("```"):
                fence = None if fence is not None else stripped[3:].strip()
                block += 1
                i += 1
                continue
            if fence in ("sh", "bash", "shell") and stripped.startswith("scadray "):
                start = i
                cmd = stripped
                while cmd.endswith("\\") and i + 1 < len(lines):
                    i += 1
                    cmd = cmd[:-1].rstrip() + " " + lines[i].strip()
                found.append((rel, start + 1, cmd, block))
            i += 1
    return found


def needed_programs(cmd):
    words = cmd.split()
    need = []
    sub = words[1] if len(words) > 1 else ""
    if (sub in ("check", "converge") and "--openscad" not in words) or \
            (sub == "report" and "--from" not in words):
        need.append("povray")
    if "--openscad" in words or "--openscad-only" in words:
        need.append("openscad")
    if "--frames" in words and "--frame" not in words:
        need.append("ffmpeg")
    if "/usr/share/openscad/" in cmd:
        need.append("openscad")
    return need


def check_commands(files, scadray, fail, skipped):
    """Runs the commands block by block: the commands of one ```sh block run in order in one
    fresh scratch folder (a later line may read what an earlier one wrote), each block in its
    own folder."""
    bindir = tempfile.mkdtemp(prefix="scadray-docs-bin-")
    os.symlink(os.path.realpath(scadray), os.path.join(bindir, "scadray"))
    env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""))
    blocks = {}
    for rel, n, cmd, block in doc_commands(files):
        blocks.setdefault((rel, block), []).append((n, cmd))
    try:
        for (rel, _), commands in blocks.items():
            work = tempfile.mkdtemp(prefix="scadray-docs-")
            try:
                for d in ("scenes", "tests"):
                    os.symlink(os.path.join(ROOT, d), os.path.join(work, d))
                for n, cmd in commands:
                    where = f"{rel}:{n}"
                    missing = [p for p in needed_programs(cmd) if shutil.which(p) is None]
                    if missing:
                        skipped.append(f"{where}: needs {', '.join(missing)}")
                        break  # later lines of the block may need this one's output
                    print(f"[commands] {where}: {cmd}", flush=True)
                    try:
                        r = subprocess.run(["/bin/sh", "-c", cmd], cwd=work, env=env,
                                           capture_output=True, timeout=COMMAND_TIMEOUT_S)
                    except subprocess.TimeoutExpired:
                        fail("commands", where, f"'{cmd}' ran past {COMMAND_TIMEOUT_S} s")
                        break
                    if r.returncode != 0:
                        err = r.stderr.decode(errors="replace").strip().splitlines()[-5:]
                        fail("commands", where,
                             f"'{cmd}' exited {r.returncode}: " + " | ".join(err))
                        break
            finally:
                shutil.rmtree(work, ignore_errors=True)
    finally:
        shutil.rmtree(bindir, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scadray", help="the scadray binary the manual's commands run")
    ap.add_argument("--only", help="comma-separated checks to run")
    ap.add_argument("--list", action="store_true", help="list the manual's commands and exit")
    args = ap.parse_args()
    files = tracked_files()
    if args.list:
        for rel, n, cmd, _ in doc_commands(files):
            print(f"{rel}:{n}: {cmd}")
        return 0
    only = set(args.only.split(",")) if args.only else None
    failures, skipped = [], []

    def fail(check, where, what):
        failures.append(f"{where}: [{check}] {what}")

    def wanted(name):
        return only is None or name in only

    if wanted("links"):
        check_links(files, fail)
    if wanted("citations"):
        check_citations(files, fail)
    if wanted("worklog"):
        check_worklog(files, fail)
    if wanted("readme"):
        check_readme(fail)
    if wanted("version"):
        check_version(fail)
    if wanted("commands") and args.scadray:
        check_commands(files, args.scadray, fail, skipped)
    for f in failures:
        print(f, file=sys.stderr)
    for s in skipped:
        print(f"not run: {s}", file=sys.stderr)
    if failures:
        print(f"{len(failures)} documentation problem(s)", file=sys.stderr)
        return 1
    if skipped:
        print(f"SKIPPED: {len(skipped)} command(s) need a program that is not installed")
        return 77
    print("documentation: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
