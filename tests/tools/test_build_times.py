#!/usr/bin/python3
"""tools/build-times on a compile_commands.json of its own: two tiny translation units, one that
compiles and one that does not; the build's object files are never written."""
import contextlib
import csv
import importlib.machinery
import importlib.util
import io
import json
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
loader = importlib.machinery.SourceFileLoader("build_times", os.path.join(HERE, "..", "..", "tools", "build-times"))
spec = importlib.util.spec_from_loader("build_times", loader)
build_times = importlib.util.module_from_spec(spec)
loader.exec_module(build_times)


class BuildTimes(unittest.TestCase):
    def test_launcher_dropped_and_outputs_redirected(self):
        entry = {"command": "/usr/bin/ccache /usr/bin/c++ -O2 -MD -MT a.o -MF 'dir with space/a.d' -o a.o -c a.cpp"}
        args = build_times.compile_arguments(entry)
        self.assertEqual(args[0], "/usr/bin/c++")
        self.assertIn("dir with space/a.d", args)
        out = build_times.redirect_outputs(args, "/scratch")
        self.assertEqual(out[out.index("-o") + 1], "/scratch/object.o")
        self.assertEqual(out[out.index("-MF") + 1], "/scratch/object.d")
        self.assertEqual(out[-2:], ["-c", "a.cpp"])

    def test_times_each_unit_and_reports_failures(self):
        with tempfile.TemporaryDirectory() as tmp:
            src = os.path.join(tmp, "src")
            os.makedirs(src)
            with open(os.path.join(src, "good.cpp"), "w") as f:
                f.write("int good() { return 1; }\n")
            with open(os.path.join(src, "bad.cpp"), "w") as f:
                f.write("int bad( { return; }\n")
            entries = [{"directory": tmp, "file": os.path.join(src, name),
                        "command": f"c++ -o {name}.o -c {os.path.join(src, name)}"} for name in ("good.cpp", "bad.cpp")]
            with open(os.path.join(tmp, "compile_commands.json"), "w") as f:
                json.dump(entries, f)
            out, err = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                rc = build_times.main(["--build", tmp, "--top", "0", "--csv", os.path.join(tmp, "t.csv")])
            self.assertEqual(rc, 1)  # bad.cpp failed
            self.assertIn("bad.cpp failed", err.getvalue())
            self.assertRegex(out.getvalue(), r"\| good\.cpp \| [0-9.]+ \| [0-9.]+ \|")
            self.assertIn("| bad.cpp (failed) |", out.getvalue())
            self.assertIn("all 2 translation units", out.getvalue())
            with open(os.path.join(tmp, "t.csv")) as f:
                rows = {os.path.basename(r["file"]): r for r in csv.DictReader(f)}
            self.assertEqual(rows["good.cpp"]["exit"], "0")
            self.assertNotEqual(rows["bad.cpp"]["exit"], "0")
            self.assertFalse(os.path.exists(os.path.join(tmp, "good.cpp.o")))  # scratch, not the build's

            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                self.assertEqual(build_times.main(["--build", tmp, "--filter", "good"]), 0)
            with self.assertRaises(SystemExit):
                build_times.main(["--build", tmp, "--filter", "nothing-matches"])

            # As a build's launcher: each compile's times appended to a log, its status passed on.
            log = os.path.join(tmp, "times.jsonl")
            for name, expected in (("good.cpp", 0), ("bad.cpp", 1)):
                with contextlib.redirect_stderr(io.StringIO()):
                    rc = build_times.main(["--record", log, "--", "c++", "-o", os.path.join(tmp, name + ".o"),
                                           "-c", os.path.join(src, name)])
                self.assertEqual(rc != 0, bool(expected))
            self.assertTrue(os.path.exists(os.path.join(tmp, "good.cpp.o")))  # the launcher's compile is the build's
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                self.assertEqual(build_times.main(["--log", log, "--by", "user"]), 1)
            self.assertIn("all 2 translation units, as the build ran them", out.getvalue())
            self.assertIn("| bad.cpp (failed) |", out.getvalue())
            with self.assertRaises(SystemExit):
                build_times.main(["--record", log, "c++"])


if __name__ == "__main__":
    unittest.main()
