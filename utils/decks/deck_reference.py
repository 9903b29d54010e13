#!/usr/bin/python3
"""Generates docs/deck-reference.md from the apps' own declarations.

Every app prints its full validated parameter list with `--print-defaults`: each key's
type, default, doc string and requirement (range, choices). This script runs each app
and turns that XML into one Markdown table per sublist, so the reference can never drift
from the code.

Usage: utils/decks/deck_reference.py BUILD_DIR [OUTPUT.md]   (default docs/deck-reference.md)
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "utils", "docs"))
import generated_pages  # noqa: E402 (the header of a generated page: command and code version)

COMMAND = "/usr/bin/python3 utils/decks/deck_reference.py build"
APPS = ["cell3d", "twocell3d", "suspension3d", "tether2d", "cellshape", "curvature_report"]


def find_app(build, name):
    path = os.path.join(build, "apps", name, name)
    return path if os.path.exists(path) else None


def parse(xml_text):
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    return ET.fromstring(xml_text, parser=parser)


def rows(element, path, out):
    """Collects (sublist path, key, type, default, doc) rows in deck order."""
    doc = ""
    sub_docs = {}
    for child in element:
        if child.tag is ET.Comment:
            # The apps write "--" as "- -" inside XML comments, where "--" may not appear.
            doc = child.text.strip().replace("- -", "--")
            continue
        name = child.get("name")
        if child.tag == "Parameter":
            out.append((path, name, child.get("type"), child.get("value"), doc))
        elif child.tag == "ParameterList":
            sub_docs[name] = doc
            if len(child) == 0:
                # A sublist without declared keys (one whose entries a library checks, such as
                # Solver/Belos): its doc string says what goes in it.
                out.append((path + [name], None, None, None, doc))
            rows(child, path + [name], out)
        doc = ""
    return sub_docs


def markdown_for(app, root):
    table = []
    rows(root, [], table)
    lines = [f"## `{app}`", ""]
    current = None
    for path, key, typ, value, doc in table:
        section = "/".join(path) if path else "(top level)"
        if section != current:
            lines += ["", f"### {section}", "", "| key | type | default | meaning |", "|---|---|---|---|"]
            current = section
        if key is None:
            lines[-2:] = [doc]  # no table: the doc string says what goes in it
            continue
        doc = doc.replace("|", "\\|")
        lines.append(f"| `{key}` | {typ} | `{value}` | {doc} |")
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return
    if len(sys.argv) < 2 or len(sys.argv) > 3:
        sys.exit("usage: utils/decks/deck_reference.py BUILD_DIR [OUTPUT.md] (see --help)")
    build = sys.argv[1]
    output = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "deck-reference.md")
    parts = [
        "# Deck reference",
        "",
        generated_pages.header_line(COMMAND, ROOT),
        "",
        "From each app's `--print-defaults`: every key",
        "an app accepts, its type, its default and what it means, including the allowed range",
        "or choices (\"Must be ...\"). A deck needs only the keys it changes; every other key",
        "takes the default shown. Keys are case- and space-sensitive; a misspelt key is",
        "rejected with a suggestion. Regenerate after changing a declaration (the test",
        "`docs_deck_reference_is_current`, `ctest -L docs`, fails while this page and the apps",
        "disagree):",
        "",
        f"    {COMMAND}",
        "",
    ]
    found = 0
    for app in APPS:
        exe = find_app(build, app)
        if exe is None:
            continue
        result = subprocess.run([exe, "--print-defaults"], capture_output=True, text=True, check=True)
        parts.append(markdown_for(app, parse(result.stdout)))
        found += 1
    if found == 0:
        sys.exit(f"no apps found under {build}/apps: build first")
    with open(output, "w", encoding="utf-8") as f:
        f.write("\n".join(parts))
    print(f"wrote {output} ({found} apps)")


if __name__ == "__main__":
    main()
