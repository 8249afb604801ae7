#!/usr/bin/python3
"""Writes DIR/fixture.cpp for the test lengths.names_the_one_over_the_limit
(tests/long_definitions.cmake): a class of exactly 120 lines, the limit, and one of 121, each
counted from the line that opens it to the line that closes it."""
import pathlib
import sys


def class_of(name, lines):
    members = [f"  int member_{i} = {i};" for i in range(lines - 3)]
    return [f"class {name} {{", " public:", *members, "};"]


out = pathlib.Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)
text = class_of("AtTheLimit", 120) + [""] + class_of("OneLineTooLong", 121)
(out / "fixture.cpp").write_text("\n".join(text) + "\n")
