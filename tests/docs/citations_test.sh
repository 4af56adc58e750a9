#!/usr/bin/env bash
# Every repository path a file cites exists, so a comment never leans on a file a reader cannot
# open. Checked in every tracked file (or, outside a git checkout, every file but build folders):
# paths under one of the repository's top-level folders (`docs/design.md`, `configs/ocp/*.yaml`,
# `tests/apps/plots_test.sh`), bare upper-case pages (`README.md`), design notes (`notes/*.md`),
# and sections of pages (`design.md#conventions` must be a heading of design.md). Then a planted
# tree with good and bad citations: each bad one must be named, no good one.
# Usage: citations_test.sh SOURCE_DIR
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/../apps/cli_test_lib.sh" root "$@"

# check_tree ROOT: prints "FILE:LINE: cites ..." for each bad citation; exit 1 when there is one.
check_tree() {
  "$PY" - "$1" tests/docs/citations_test.sh <<'PY'
import os, re, subprocess, sys

root, this_test = sys.argv[1], sys.argv[2]

def tracked_files():
    top = subprocess.run(["git", "-C", root, "rev-parse", "--show-toplevel"],
                         capture_output=True, text=True)
    if top.returncode == 0 and os.path.samefile(top.stdout.strip(), root):
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True,
                             check=True).stdout
        return [f for f in out.decode().split("\0") if f]
    files = []
    for d, subdirs, names in os.walk(root):
        subdirs[:] = [s for s in subdirs
                      if not s.startswith(".") and not (d == root and s.startswith("build"))]
        files += [os.path.relpath(os.path.join(d, n), root) for n in names]
    return files

files = tracked_files()
folders = sorted({f.split("/")[0] for f in files if "/" in f} | {"notes", "seeds"})
# A path under a top-level folder, a bare upper-case page, or a page with a section; never
# right after a path character, so "$ROOT/configs/x.yaml" and "../robots/x.yaml" (checked by the
# tests that load them) are left alone, and a "\." (a regular expression) ends a path.
TOKEN = re.compile(
    r"(?<![\w.$/{}@\\-])(?:(?:%s)/(?:\{[\w.,*-]*\}|[\w./*+-])*[\w*}]"
    r"|[A-Z][A-Z0-9_]*\.md\b|[\w./-]*\.md#[\w-]+)(?:#[\w-]+)?" % "|".join(map(re.escape, folders)))
# Upper-case words that stand for a name (`results/NAME/summary.json`, `OUT.tmp-PID`).
PLACEHOLDER = re.compile(
    r"(?<![A-Za-z])(?:NAME|DIR|OUT|COMMAND|TARGET|FILE|PID|GAIT|STUDY|ROBOT|CONFIG|N)(?![A-Za-z])")

def braces(path):
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    return [x for alt in m.group(1).split(",")
            for x in braces(path[:m.start()] + alt + path[m.end():])]

def exists(base, path):
    import glob
    return any(glob.glob(os.path.join(root, base, p)) for p in braces(path))

def resolves(citing, path):
    """The folder the path is relative to (citing file's, its top-level folder, the root; a
    docs/src/ template's page lives in docs/), or None."""
    bases = [os.path.dirname(citing), citing.split("/")[0] if "/" in citing else ".", "."]
    if citing.startswith("docs/src/"):
        bases.append("docs")
    for candidate in (path, PLACEHOLDER.sub("*", path)):
        for base in bases:
            if exists(base, candidate):
                return base
    last = path.rsplit("/", 1)[-1]
    for base in bases:
        # A built program named after its source (bench/ocp_study), or a path cut by "\.".
        if "." not in last and exists(base, path + ".*"):
            return base
    # results/ holds curated outputs; a command's output inside a committed folder counts.
    if path.startswith("results/") and exists(".", os.path.dirname(path)):
        return "."
    return None

def slugs(page):
    out, fenced = set(), False
    for line in open(page, encoding="utf-8"):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6} ", line):
            title = line.lstrip("#").strip().lower()
            out.add(re.sub(r"[^\w\- ]", "", title).replace(" ", "-"))
    return out

bad = 0
for citing in files:
    if citing == this_test:
        continue
    try:
        with open(os.path.join(root, citing), "rb") as f:
            data = f.read()
    except OSError:
        continue
    if b"\0" in data[:8192]:
        continue
    for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
        for token in TOKEN.findall(line):
            path, _, anchor = token.partition("#")
            path = re.sub(r"/+", "/", path).rstrip("/")
            base = resolves(citing, path)
            if base is None:
                print(f"{citing}:{number}: cites {path}, which does not exist")
                bad += 1
            elif anchor and path.endswith(".md") and anchor not in slugs(
                    os.path.join(root, base, path)):
                print(f"{citing}:{number}: cites {path}#{anchor}, but {path} has no such heading")
                bad += 1
sys.exit(1 if bad else 0)
PY
}

check_tree "$ROOT" >"$TMP/report" || {
  cat "$TMP/report"
  fail "citations of files or sections that do not exist"
}
echo "every cited repository path and section exists"

# The planted tree: a page with one section, a config, and citations good and bad.
P="$TMP/planted"
mkdir -p "$P/docs" "$P/configs/robots" "$P/src"
printf '# Page\n## The export contract\n' >"$P/docs/page.md"
printf 'name: r\n' >"$P/configs/robots/r.yaml"
cat >"$P/src/a.cpp" <<'EOF'
// good: docs/page.md#the-export-contract, configs/robots/*.yaml, configs/robots/NAME.yaml,
// docs/{page,link}.md
// bad: docs/gone.md, DESIGN.md, notes/mu2004.md, configs/robots/gone.yaml,
// docs/page.md#no-such-section
EOF
printf 'See [the contract](page.md#the-export-contract) and [x](page.md#nope).\n' >"$P/docs/link.md"
check_tree "$P" >"$TMP/planted.out" && fail "a planted bad citation passed"
for want in "src/a.cpp:3: cites docs/gone.md," "src/a.cpp:3: cites DESIGN.md," \
  "src/a.cpp:3: cites notes/mu2004.md," "src/a.cpp:3: cites configs/robots/gone.yaml," \
  "src/a.cpp:4: cites docs/page.md#no-such-section, but" "docs/link.md:1: cites page.md#nope, but"; do
  grep -qF -- "$want" "$TMP/planted.out" || fail "not reported: $want; got: $(cat "$TMP/planted.out")"
done
[[ $(wc -l <"$TMP/planted.out") -eq 6 ]] || fail "a good citation was reported: $(cat "$TMP/planted.out")"
echo "citations: the tree passes; a planted tree's six bad citations are named, its good ones pass"
