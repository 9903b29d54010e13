#!/usr/bin/python3
"""Writes Capsula decks from "List/Sub/Key=value" assignments, typed and checked against the
app's own `--print-defaults`.

  deck_writer.py studies [--build DIR] [--root DIR] [APP...]
      writes the study decks of input/cell3d, input/twocell3d and input/tether2d
      (definitions in study_decks.py); APP limits it to those apps
  deck_writer.py derive --app APP [--build DIR] DECK [--set "List/Key=value"]... --output FILE
      writes DECK with the assignments applied, as `APP DECK --set ...` would read it
  deck_writer.py manifest --app APP [--build DIR] --runs DIR MANIFEST
      derives many decks at once: every line of MANIFEST is NAME<TAB>DECK[<TAB>List/Key=value]...
      and becomes DIR/NAME.xml (what the study scripts run)

Every assignment is checked before anything is written: the key must be one the app declares
(a misspelt key is named, with the closest valid one), and the value must read as the key's
type (double, int, bool, string, Array(double)); ranges and choices are checked by the app
when it runs the deck. "Cells/Cell 1/..." is typed by "Cells/Cell 0/...": numbered sublists
share the schema of the first. A deck holds only the keys it sets, in the order they are
set; every other key keeps the app's default. Debian's /usr/bin/python3, standard library only.
"""
import argparse
import difflib
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
WRITER = "utils/decks/deck_writer.py"


class DeckError(Exception):
    """A bad key, value or deck, with a message naming it."""


class Schema:
    """The keys an app declares and their types, from `APP --print-defaults`."""

    def __init__(self, app, xml_text):
        self.app = app
        self.root = ET.fromstring(xml_text)

    @classmethod
    def from_build(cls, app, build):
        exe = os.path.join(build, "apps", app, app)
        if not os.access(exe, os.X_OK):
            raise DeckError(f"no {exe}: build the app first (cmake --build {build} --target {app}) "
                            "or pass --build DIR")
        result = subprocess.run([exe, "--print-defaults"], capture_output=True, text=True)
        if result.returncode != 0:
            raise DeckError(f"{exe} --print-defaults failed: {result.stderr.strip()}")
        return cls(app, result.stdout)

    @staticmethod
    def _child(element, name):
        child = child_named(element, name)
        numbered = re.fullmatch(r"(.*) [0-9]+", name)
        if child is None and numbered:
            # "Cell 1", "Cell 2", ... are typed by "Cell 0".
            child = child_named(element, numbered.group(1) + " 0")
        return child

    def type_of(self, path):
        """The declared type of the key at PATH ("Flow/Capillary number"), or a DeckError."""
        element = self.root
        parts = path.split("/")
        for depth, part in enumerate(parts):
            child = self._child(element, part)
            if child is None:
                names = [c.get("name") for c in element if c.get("name")]
                where = "/".join(parts[:depth]) or "the top level"
                message = f"{self.app}: '{path}' is not a key of this app: no '{part}' in {where}."
                guess = difflib.get_close_matches(part, names, n=1)
                if guess:
                    message += f" Did you mean '{'/'.join(parts[:depth] + guess)}'?"
                raise DeckError(message + f" Run `{self.app} --print-defaults` for every key.")
            wants_list = depth < len(parts) - 1
            if wants_list != (child.tag == "ParameterList"):
                kind = "a sublist" if child.tag == "ParameterList" else "a value"
                raise DeckError(f"{self.app}: '{'/'.join(parts[:depth + 1])}' is {kind}.")
            element = child
        return element.get("type")


def child_named(element, name):
    for child in element:
        if child.get("name") == name:
            return child
    return None


REAL = r"[-+]?(\d+\.?\d*([eE][-+]?\d+)?|\.\d+([eE][-+]?\d+)?|inf|nan)"


def check_value(app, path, kind, text):
    """Raises a DeckError unless TEXT reads as a value of type KIND."""
    ok = {"double": lambda t: re.fullmatch(REAL, t.strip()) is not None,
          "int": lambda t: re.fullmatch(r"[-+]?\d+", t.strip()) is not None,
          "bool": lambda t: t.strip() in ("true", "false"),
          "string": lambda t: True,
          "Array(double)": lambda t: re.fullmatch(r"\{\s*(" + REAL + r"(\s*,\s*" + REAL + r")*)?\s*\}",
                                                  t.strip()) is not None}.get(kind)
    if ok is None:
        raise DeckError(f"{app}: '{path}' has type {kind}, which this writer cannot set; edit the deck.")
    if not ok(text):
        raise DeckError(f"{app}: '{path}' = '{text}' is not a value of type {kind}.")


def text_of(value):
    """The deck text of a value: strings verbatim, booleans as true/false, numbers shortest."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "{" + ", ".join(text_of(v) for v in value) + "}"
    if isinstance(value, float):
        return repr(value)
    return str(value)


class Deck:
    """An ordered set of assignments: sublists and values in the order they were first set."""

    def __init__(self, schema, name=None):
        self.schema = schema
        self.name = name or schema.app
        self.items = {}   # name -> ("list", dict) or ("value", type, text)

    @classmethod
    def read(cls, schema, path):
        """A deck file as it stands (types from the file; the app checks them when it runs)."""
        try:
            root = ET.parse(path).getroot()
        except (OSError, ET.ParseError) as e:
            raise DeckError(f"cannot read deck '{path}': {e}") from e
        deck = cls(schema, root.get("name"))

        def load(element, items):
            for child in element:
                if child.tag == "ParameterList":
                    sub = {}
                    items[child.get("name")] = ("list", sub)
                    load(child, sub)
                elif child.tag == "Parameter":
                    items[child.get("name")] = ("value", child.get("type"), child.get("value"))
        load(root, deck.items)
        return deck

    def set(self, path, value):
        kind = self.schema.type_of(path)
        text = text_of(value)
        check_value(self.schema.app, path, kind, text)
        parts = path.split("/")
        items = self.items
        for part in parts[:-1]:
            entry = items.setdefault(part, ("list", {}))
            items = entry[1]
        items[parts[-1]] = ("value", kind, text)
        return self

    def assign(self, assignment):
        """One "List/Key=value" assignment, as the apps' --set reads it."""
        key, eq, value = assignment.partition("=")
        if not eq or not key.strip():
            raise DeckError(f"'{assignment}': expected \"List/Sub/Key=value\"")
        return self.set(key.strip(), value)

    def xml(self, comment=None):
        lines = []
        if comment:
            lines.append(f"<!-- {comment} -->")

        def emit(name, items, depth):
            pad = "  " * depth
            lines.append(f'{pad}<ParameterList name="{escape(name)}">')
            for key, entry in items.items():
                if entry[0] == "list":
                    emit(key, entry[1], depth + 1)
                else:
                    lines.append(f'{pad}  <Parameter name="{escape(key)}" type="{entry[1]}" '
                                 f'value="{escape(entry[2])}"/>')
            lines.append(f"{pad}</ParameterList>")
        emit(self.name, self.items, 0)
        return "\n".join(lines) + "\n"

    def write(self, path, comment=None):
        """Writes the deck atomically (a temporary file, then renamed)."""
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(self.xml(comment))
        os.replace(path + ".tmp", path)


def escape(text):
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))


def comment_safe(text):
    while "--" in text:   # "--" may not appear inside an XML comment
        text = text.replace("--", "- -")
    return text


def derive(schema, deck_path, assignments):
    deck = Deck.read(schema, deck_path)
    for assignment in assignments:
        deck.assign(assignment)
    return deck


def derived_comment(deck_path, assignments):
    source = os.path.relpath(os.path.abspath(deck_path), ROOT)
    if source.startswith(".."):
        source = deck_path
    changes = "; ".join(assignments) if assignments else "no changes"
    return comment_safe(f"{source} with {changes} (written by {WRITER})")


def write_studies(build, root, apps):
    import study_decks
    total = 0
    for app in apps:
        schema = Schema.from_build(app, build)
        decks = list(study_decks.DECKS[app]())
        # Every deck is built (and so checked) before any file is written.
        built = []
        for relative, comment, assignments in decks:
            deck = Deck(schema)
            for path, value in assignments:
                deck.set(path, value)
            built.append((relative, comment, deck))
        for relative, comment, deck in built:
            deck.write(os.path.join(root, relative),
                       comment_safe(comment.replace("%WRITER%", WRITER)))
        print(f"{app}: {len(built)} decks under {os.path.join(root, 'input', app)}")
        total += len(built)
    return total


def read_manifest(path):
    runs = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            fields = line.rstrip("\n").split("\t")
            if not line.strip():
                continue
            if len(fields) < 2 or not fields[0] or not fields[1]:
                raise DeckError(f"{path}:{number}: expected NAME<TAB>DECK[<TAB>List/Key=value]...")
            runs.append((fields[0], fields[1], [a for a in fields[2:] if a]))
    return runs


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=WRITER, description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n".join(__doc__.split("\n")[2:]))
    commands = parser.add_subparsers(dest="command", required=True)
    studies = commands.add_parser("studies", help="write the study decks under input/")
    studies.add_argument("apps", nargs="*", metavar="APP", help="cell3d, twocell3d, tether2d (default: all)")
    studies.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (default: build)")
    studies.add_argument("--root", default=ROOT, help="where input/ is (default: the repository)")
    one = commands.add_parser("derive", help="write one deck with assignments applied")
    one.add_argument("deck", metavar="DECK")
    one.add_argument("--app", required=True)
    one.add_argument("--build", default=os.path.join(ROOT, "build"))
    one.add_argument("--set", action="append", default=[], metavar="List/Key=value", dest="assignments")
    one.add_argument("--output", required=True, metavar="FILE")
    many = commands.add_parser("manifest", help="derive the decks listed in a manifest")
    many.add_argument("manifest", metavar="MANIFEST")
    many.add_argument("--app", required=True)
    many.add_argument("--build", default=os.path.join(ROOT, "build"))
    many.add_argument("--runs", required=True, metavar="DIR", help="writes DIR/NAME.xml for every line")
    args = parser.parse_args(argv)
    sys.path.insert(0, HERE)
    try:
        if args.command == "studies":
            import study_decks
            apps = args.apps or list(study_decks.DECKS)
            unknown = [a for a in apps if a not in study_decks.DECKS]
            if unknown:
                raise DeckError(f"no study decks for {', '.join(unknown)} (known: {', '.join(study_decks.DECKS)})")
            write_studies(args.build, args.root, apps)
        elif args.command == "derive":
            schema = Schema.from_build(args.app, args.build)
            derive(schema, args.deck, args.assignments).write(
                args.output, derived_comment(args.deck, args.assignments))
        else:
            schema = Schema.from_build(args.app, args.build)
            runs = read_manifest(args.manifest)
            decks = [(name, derive(schema, deck, assignments), derived_comment(deck, assignments))
                     for name, deck, assignments in runs]
            for name, deck, comment in decks:
                deck.write(os.path.join(args.runs, name + ".xml"), comment)
            print(f"deck_writer: {len(decks)} decks in {args.runs}")
    except DeckError as e:
        sys.exit(f"deck_writer: error: {e}")


if __name__ == "__main__":
    main()
