#!/usr/bin/python3
"""Renders the README and the docs/ pages from their templates in docs/src/, so that every
number they show is read from the file in results/ that made it.

    scripts/docs.py render [--root DIR]   write README.md and docs/*.md from docs/src/*.md
    scripts/docs.py check  [--root DIR]   exit 1, naming the first difference, when a rendered
                                          page differs from the committed one (a number changed
                                          by hand, or a result regenerated without rendering),
                                          or when a page links a file that is not there (a
                                          picture a regeneration deleted)

In a template, `{{ EXPR }}` or `{{ EXPR | SPEC }}` is replaced by the value of the Python
expression EXPR formatted with the format spec SPEC (e.g. `.3g`). EXPR may call:
    j(FILE, KEY)          a value of a JSON file; KEY is dotted, list items by index (`a.0.b`)
    c(FILE, COLUMN, **W)  a CSV cell: the column of the one row whose cells equal W
    md(FILE)              a whole markdown file (a table written by a script)
and abs, min, max, round, len, format, str, sum, zip, sorted. FILE is relative to the repository root. `docs/src/README.md`
becomes `README.md`; `docs/src/NAME.md` becomes `docs/NAME.md`.
"""
import argparse
import csv
import json
import re
import sys
from pathlib import Path

PLACEHOLDER = re.compile(r"\{\{(.+?)\}\}", re.S)
# The target of a markdown link or image: ](path) or ](path#anchor).
LINK = re.compile(r"\]\(([^)#\s]+)")


class Sources:
    """Reads the files that templates cite, each once."""

    def __init__(self, root):
        self.root = root
        self.cache = {}

    def _read(self, name, parse):
        if name not in self.cache:
            path = self.root / name
            if not path.is_file():
                raise KeyError(f"cited file {name} does not exist")
            self.cache[name] = parse(path)
        return self.cache[name]

    def json_value(self, name, key):
        value = self._read(name, lambda p: json.loads(p.read_text()))
        for part in key.split("."):
            value = value[int(part)] if isinstance(value, list) else value[part]
        return value

    def _csv_rows(self, name, where):
        """The rows of CSV file `name` whose cells equal every value of `where`."""
        rows = self._read(name, lambda p: list(csv.DictReader(p.open())))
        return [r for r in rows if all(r.get(k) == str(v) for k, v in where.items())]

    def csv_value(self, name, column, **where):
        hits = self._csv_rows(name, where)
        if len(hits) != 1:
            raise KeyError(f"{name}: {len(hits)} rows match {where}, expected 1")
        cell = hits[0][column]
        try:
            return float(cell)
        except ValueError:
            return cell

    def csv_values(self, name, column, **where):
        """Every matching row's cell, as numbers: for a range over many rows."""
        hits = [float(r[column]) for r in self._csv_rows(name, where)]
        if not hits:
            raise KeyError(f"{name}: no row matches {where}")
        return hits

    def markdown(self, name):
        """The file's text, its headings two levels down: an included table's own title sits
        under the section that includes it, not beside the page's title."""
        text = self._read(name, lambda p: p.read_text()).rstrip("\n")
        lines, fenced = [], False
        for line in text.split("\n"):
            fenced ^= line.startswith("```")
            lines.append(re.sub(r"^(#+) ", r"##\1 ", line) if not fenced else line)
        return "\n".join(lines)

    def namespace(self):
        return {"j": self.json_value, "c": self.csv_value, "cs": self.csv_values, "md": self.markdown,
                "interval": lambda a, b: signed_interval(a, b, 0),
                "interval1": lambda a, b: signed_interval(a, b, 1),
                "abs": abs, "min": min, "max": max, "round": round, "len": len,
                "format": format, "str": str, "sum": sum, "zip": zip, "sorted": sorted,
                "__builtins__": {}}


def signed(x, digits):
    """x with its sign, as '%+.Nf' writes it, but 0 bare (not '+0' or '-0')."""
    text = f"{x:+.{digits}f}"
    return text[1:] if float(text) == 0 else text


def signed_interval(a, b, digits):
    """A range of errors or pushes around the nominal: '-10 .. +5', '-10 .. 0'."""
    return f"{signed(a, digits)} .. {signed(b, digits)}"


def render_text(template, sources, where):
    namespace = sources.namespace()

    def substitute(match):
        expr, _, spec = match.group(1).partition("|")
        try:
            value = eval(expr.strip(), namespace)  # noqa: S307 (our own templates)
            return format(value, spec.strip())
        except Exception as e:  # the message must name the placeholder whatever went wrong
            line = template.count("\n", 0, match.start()) + 1
            raise SystemExit(f"docs: {where}:{line}: {{{{{match.group(1)}}}}}: {e}")

    return PLACEHOLDER.sub(substitute, template)


def pages(root):
    for template in sorted((root / "docs" / "src").glob("*.md")):
        target = root / "README.md" if template.name == "README.md" else root / "docs" / template.name
        yield template, target


def missing_links(text, page):
    """Local link and image targets of a page that do not exist, relative to the page."""
    return [t for t in LINK.findall(text)
            if not re.match(r"[a-z]+:", t) and not (page.parent / t).exists()]


def first_difference(a, b):
    for i, (x, y) in enumerate(zip(a.splitlines(), b.splitlines()), 1):
        if x != y:
            return i, x, y
    return min(len(a.splitlines()), len(b.splitlines())) + 1, "(end)", "(end)"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["render", "check"])
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    args = parser.parse_args()
    sources = Sources(args.root)
    stale = 0
    for template, target in pages(args.root):
        rendered = render_text(template.read_text(), sources, template.relative_to(args.root))
        name = target.relative_to(args.root)
        if args.mode == "render":
            target.write_text(rendered)
            continue
        committed = target.read_text() if target.is_file() else ""
        if committed != rendered:
            line, have, want = first_difference(committed, rendered)
            print(f"docs: {name}:{line} differs from its template and results/:\n"
                  f"  committed: {have}\n  rendered:  {want}", file=sys.stderr)
            stale += 1
        for link in missing_links(rendered, target):
            print(f"docs: {name} links {link}, which is not there", file=sys.stderr)
            stale += 1
    if args.mode == "check":
        print(f"docs: {stale} differences or missing links"
              if stale else "docs: every page matches its template and results/, and its links")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
