"""Citations a reader can look up (docs/architecture.md §7): no source document is named by
an internal file name, no design document but docs/architecture.md is referred to, every
numpydoc References entry names its docs/references.bib key, and every key and section
cited exists."""

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
SCANNED = ["src", "tests", "benchmarks", "docs", "README.md", "CITATION.cff"]
TEXT_SUFFIXES = {".py", ".md", ".yaml", ".yml", ".json", ".bib", ".cff", ".txt", ".toml", ".html", ".cfg"}

#: Internal names of the source documents: ``NNN_`` then 16 hex digits, or abbreviated
#: ``00N_…`` (also JSON-escaped, as in the shipped schema).
SEED_NAME = re.compile(r"[0-9]{3}_[0-9a-f]{16}|\b0[0-9]{2}_(?:…|\\u2026|\.\.\.)")
#: The original brief's file name, assembled so that this file does not contain it.
OLD_DESIGN = re.compile("DESIGN" + r"\.md")
BIB_KEY = re.compile(r"\(docs/references\.bib: ([a-z][a-z0-9_-]*)\)")
ARCH_SECTION = re.compile(r"docs/architecture\.md`*\s+§(\d+(?:\.\d+)?)")


def _files() -> list[Path]:
    out = []
    for name in SCANNED:
        path = ROOT / name
        if path.is_file():
            out.append(path)
        elif path.is_dir():
            out += [
                p
                for p in sorted(path.rglob("*"))
                if p.is_file() and p.suffix in TEXT_SUFFIXES and "__pycache__" not in p.parts
            ]
    return out


FILES = _files()
PY_FILES = [p for p in FILES if p.suffix == ".py"]


def _bib_keys() -> set[str]:
    text = (ROOT / "docs" / "references.bib").read_text(encoding="utf-8")
    return set(re.findall(r"^@\w+\{([^,\s]+),", text, flags=re.M))


def _architecture_sections() -> set[str]:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    return set(re.findall(r"^#{2,3} (\d+(?:\.\d+)?)\.? ", text, flags=re.M))


def _docstrings(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    nodes = [tree] + [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))]
    return [d for d in (ast.get_docstring(n) for n in nodes) if d]


def test_scan_covers_the_project():
    names = {p.relative_to(ROOT).as_posix() for p in FILES}
    assert "README.md" in names and "docs/architecture.md" in names and "docs/references.bib" in names
    assert "src/taut/schema/robot.schema.json" in names
    assert any(n.startswith("src/taut/examples/") for n in names)
    assert len(PY_FILES) > 50


def test_patterns_catch_what_they_should():
    seed = "000_" + "3d5147f1d4639546.txt"
    assert SEED_NAME.search(f"see ``{seed}`` §2.1.4")
    abbreviated = "004" + "_"
    assert SEED_NAME.search(f"the model of ``{abbreviated}…`` §2.3.2")
    assert SEED_NAME.search(f'"collision model of ``{abbreviated}\\u2026``"')
    assert not SEED_NAME.search("Rushton 2022, §2.1.4; cable 004 of 1_000 poses")
    assert OLD_DESIGN.search("see " + "DESIGN" + ".md §2")
    assert BIB_KEY.findall("... 2022, §2.1.4. (docs/references.bib: rushton2022)") == ["rushton2022"]


@pytest.mark.parametrize("path", FILES, ids=[p.relative_to(ROOT).as_posix() for p in FILES])
def test_no_internal_document_names(path):
    text = path.read_text(encoding="utf-8")
    bad = [
        f"line {text.count(chr(10), 0, m.start()) + 1}: {m.group(0)!r}"
        for pattern in (SEED_NAME, OLD_DESIGN)
        for m in pattern.finditer(text)
    ]
    assert not bad, f"{path.relative_to(ROOT)} cites a document by an internal name: {bad}"


def test_cited_bib_keys_exist():
    keys = _bib_keys()
    assert {"rushton2022", "berti2015", "bohigas2013", "lieskovsky2020"} <= keys
    missing = {
        f"{p.relative_to(ROOT)}: {k}"
        for p in FILES
        for k in BIB_KEY.findall(p.read_text(encoding="utf-8"))
        if k not in keys and p.name != "test_citations.py"
    }
    assert not missing, f"keys not in docs/references.bib: {sorted(missing)}"


def test_every_reference_entry_names_its_bib_key():
    """Each ``.. [n]`` entry of a References section ends with ``(docs/references.bib: KEY)``."""
    bad = []
    for path in PY_FILES:
        for doc in _docstrings(path):
            if "\nReferences\n----------\n" not in doc:
                continue
            section = doc.split("\nReferences\n----------\n", 1)[1]
            entries = re.split(r"\n(?=\.\. \[\d+\])", section.strip())
            for entry in entries:
                if not entry.startswith(".. [") or not BIB_KEY.search(entry):
                    bad.append(f"{path.relative_to(ROOT)}: {entry[:70]!r}")
    assert not bad, f"References entries without a docs/references.bib key: {bad}"


def test_references_sections_are_numbered_from_one():
    bad = []
    for path in PY_FILES:
        for doc in _docstrings(path):
            if "\nReferences\n----------\n" in doc:
                numbers = [int(n) for n in re.findall(r"^\.\. \[(\d+)\]", doc.split("\nReferences\n")[1], flags=re.M)]
                if numbers != list(range(1, len(numbers) + 1)):
                    bad.append(f"{path.relative_to(ROOT)}: {numbers}")
    assert not bad, bad


def test_architecture_sections_cited_exist():
    sections = _architecture_sections()
    assert {"1", "2", "2.6", "3", "4", "4.2", "4.3", "5", "6", "7"} <= sections
    missing = {
        f"{p.relative_to(ROOT)}: §{s}"
        for p in FILES
        for s in ARCH_SECTION.findall(p.read_text(encoding="utf-8"))
        if s not in sections and p.name != "test_citations.py"
    }
    assert not missing, f"sections not in docs/architecture.md: {sorted(missing)}"


def test_source_modules_cite_publications():
    """The modules that implement the four source documents cite them in a References
    section (docs/architecture.md §7), not only in passing."""
    src = ROOT / "src" / "taut"
    for package in ("atlas", "wrapping", "dgp", "interval", "planning", "collision", "workspace"):
        for path in sorted((src / package).glob("*.py")):
            doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
            cites = re.search(r"Rushton|Berti|Bohigas|Lieskovsk", doc)
            if cites:
                assert "\nReferences\n----------\n" in doc, f"{path.relative_to(ROOT)} cites without References"


def test_bib_entries_are_well_formed():
    """Each entry closes its braces before the next begins (a merge once dropped two ``}``,
    which BibTeX reads as one entry swallowing the next)."""
    text = (ROOT / "docs" / "references.bib").read_text(encoding="utf-8")
    entries = re.split(r"^(?=@)", text, flags=re.M)[1:]
    assert len(entries) == len(_bib_keys())
    for entry in entries:
        body = entry.split("\n%", 1)[0].rstrip()
        depth = 0
        for ch in body:
            depth += {"{": 1, "}": -1}.get(ch, 0)
            assert depth >= 0, entry[:60]
        assert depth == 0 and body.endswith("}"), f"unbalanced entry: {entry[:60]!r}"
