#!/usr/bin/env python3
"""Writes the examples of a Markdown page as a shader plugin's sources: each ```glsl NAME block
as the file NAME, the ```cpp blocks, in order, as one C++ source file; and prints the names the
C++ registers (the .name of each ShaderInfo), one a line.

    extract_examples.py PAGE.md OUT_DIR SOURCE.cpp

Refuses (exit 1, naming the page and line) a glsl block without a file name, two blocks of one
name, and a page without C++."""
import os
import re
import sys


def main():
    page, out_dir, source_name = sys.argv[1:4]
    with open(page, encoding="utf-8") as f:
        lines = f.read().split("\n")
    os.makedirs(out_dir, exist_ok=True)
    files, cpp = {}, []
    i = 0
    while i < len(lines):
        opening = re.match(r"^```(\w+)\s*(\S*)\s*$", lines[i])
        if not opening:
            i += 1
            continue
        language, name, start = opening.group(1), opening.group(2), i + 1
        end = start
        while end < len(lines) and lines[end] != "```":
            end += 1
        if end == len(lines):
            sys.exit(f"{page}:{i + 1}: a code block that does not end")
        body = "\n".join(lines[start:end]) + "\n"
        if language == "glsl":
            if not name:
                sys.exit(f"{page}:{i + 1}: a glsl block names its file: ```glsl NAME.frag")
            if name in files:
                sys.exit(f"{page}:{i + 1}: a second block for {name}")
            files[name] = body
        elif language == "cpp":
            cpp.append(f'#line {start + 1} "{os.path.abspath(page)}"\n' + body)
        i = end + 1
    if not cpp:
        sys.exit(f"{page}: no ```cpp block")
    for name, body in files.items():
        write(os.path.join(out_dir, name), body)
    source = "".join(cpp)
    write(os.path.join(out_dir, source_name), source)
    for name in re.findall(r'\.name\s*=\s*"([A-Za-z_0-9]+)"', source):
        print(name)


def write(path, text):
    # Rewritten only when it changes, so that a build depending on it is not redone for nothing.
    try:
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return
    except FileNotFoundError:
        pass
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main()
