#!/usr/bin/python3
"""Checks that the documentation still tells the truth about the repository.

Scans README.md and every docs/**/*.md except docs/notebook/ (frozen, dated records) and lists,
one line each (file:line: problem), every
  - test cited as Suite.Name that no TEST(Suite, Name), TEST_F or TEST_P under test/ defines
    (a known gtest suite anywhere in the text, with Suite.* for a whole suite; an unknown suite
    when a code span holds a name shaped like a test's, e.g. `NoSuchSuite.DoesWhatItSays`);
  - repository path in backticks (include/, src/, test/, scripts/, config/, launch/, cfg/, maps/,
    docs/, microbench/, fuzz/; {a,b} and * expanded) that does not exist, and every source file
    named in backticks without its folder (`route_finish.cpp`) that no folder holds;
  - path of a developer's machine (/tmp/, /home/, /root/, /work/), and any relative path that
    climbs out of the repository (a user's clone holds nothing beside it);
  - issue number ("issue #12", "#12"): say what it was instead (not inside the tables
    scripts/bench_report.py generates, between <!-- generated: NAME --> and <!-- end -->).
Exit status 0 when there is none, 1 when there is any, 2 for a bad invocation.
Usage: scripts/check_docs.py [REPOSITORY_ROOT]   (default: the repository this script is in)
Standard library only; CTest runs it as check_docs.
"""

import glob
import os
import re
import sys

PATH_PREFIXES = ("include", "src", "test", "scripts", "config", "launch", "cfg", "maps", "docs",
                 "microbench", "fuzz")
# Files of the repository cited without their folder; not .h or .py (third-party headers and
# other projects' scripts are cited by name too).
SOURCE_EXTENSIONS = (".cpp", ".hpp", ".cc", ".sh", ".launch", ".test", ".cfg")
SKIP_DIRS = {"build", "devel", "install", "log", "out"}  # at the repository's top

TEST_DEFINITION = re.compile(r"\b(?:TEST|TEST_F|TEST_P|TYPED_TEST|TYPED_TEST_P)\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)")
# A path of the repository: one of the prefixes at the start of a word (not after "/" or a letter).
REPO_PATH = re.compile(r"(?<![\w./$-])(?:%s)/[\w./*{},+-]*" % "|".join(PATH_PREFIXES))
BARE_SOURCE = re.compile(r"(?<![\w./$<-])[\w-]+(?:%s)\b(?![\w/])" % "|".join(re.escape(e) for e in SOURCE_EXTENSIONS))
# Suite.Name, Suite.* (the whole suite) or Suite.Prefix* / Suite.Prefix… (the tests it starts).
CITATION = re.compile(r"(?<![\w.:/])([A-Z][A-Za-z0-9]*)\.([A-Z][A-Za-z0-9_]*)?([*…])?(?![\w.(])")
# A name shaped like a test's: at least three capitalised words (TheAuditFindsAChange...).
TEST_SHAPED = re.compile(r"^[A-Z][a-z0-9]+(?:[A-Z0-9][a-z0-9]*){2,}$")
MACHINE_PATH = re.compile(r"(?<![\w.~-])(?:/tmp/|/home/|/root/|/work/)")
# A relative path: "../" steps, then the first name after them.
RELATIVE_UP = re.compile(r"(?<![\w.~/-])((?:\.\./)+)([\w.-]+)")
ISSUE = re.compile(r"\b[Ii]ssues?\s+#\d+|(?<![\w&/#\[(])#\d+\b")
FENCE = re.compile(r"^\s*(```|~~~)")
GENERATED_START = re.compile(r"^\s*<!-- generated: .*-->")
GENERATED_END = re.compile(r"^\s*<!-- end -->")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")


def repository_root():
    if len(sys.argv) > 2:
        sys.stderr.write(__doc__)
        sys.exit(2)
    if len(sys.argv) == 2:
        return os.path.abspath(sys.argv[1])
    return os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def walk_files(root, top):
    for folder, dirs, files in os.walk(os.path.join(root, top)):
        # Build trees and outputs at the top only (test/ros/install/ is a test's folder).
        top_level = os.path.normpath(folder) == os.path.normpath(root)
        dirs[:] = sorted(d for d in dirs if d != ".git" and not (top_level and d in SKIP_DIRS))
        for name in sorted(files):
            yield os.path.join(folder, name)


def defined_tests(root):
    tests, suites = set(), set()
    for path in walk_files(root, "test"):
        if not path.endswith((".cpp", ".cc", ".hpp", ".h")):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            for suite, name in TEST_DEFINITION.findall(f.read()):
                tests.add((suite, name))
                suites.add(suite)
    return tests, suites


def source_basenames(root):
    names = set()
    for path in walk_files(root, "."):
        names.add(os.path.basename(path))
    return names


def documents(root):
    found = [os.path.join(root, "README.md")]
    for path in walk_files(root, "docs"):
        rel = os.path.relpath(path, root)
        if path.endswith(".md") and not rel.startswith(os.path.join("docs", "notebook") + os.sep):
            found.append(path)
    return [p for p in found if os.path.isfile(p)]


def expand_braces(text):
    match = re.search(r"\{([^{}]*)\}", text)
    if not match:
        return [text]
    out = []
    for part in match.group(1).split(","):
        out.extend(expand_braces(text[:match.start()] + part + text[match.end():]))
    return out


def path_exists(root, cited):
    cited = re.sub(r":\d+(?:-\d+)?$", "", cited)  # file:line
    cited = cited.rstrip(".,;:)")
    if not cited or cited.endswith("/.") or "..." in cited:
        return True
    for candidate in expand_braces(cited):
        full = os.path.join(root, candidate)
        if any(c in candidate for c in "*?["):
            if not glob.glob(full):
                return False
        elif not os.path.exists(full):
            return False
    return True


def lines_with_code(text):
    """(line number, the line, [code spans], in a fenced block, in a generated block) for every line."""
    fenced = generated = False
    for number, line in enumerate(text.splitlines(), 1):
        if GENERATED_START.match(line):
            generated = True
        elif GENERATED_END.match(line):
            generated = False
        if FENCE.match(line):
            fenced = not fenced
            yield number, line, [], True, generated
            continue
        if fenced:
            yield number, line, [line], True, generated
        else:
            yield number, line, [m.group(2) for m in CODE_SPAN.finditer(line)], False, generated


def check(root):
    tests, suites = defined_tests(root)
    if not tests:
        return ["test/: no TEST(Suite, Name) found (is %s the repository?)" % root]
    basenames = source_basenames(root)
    problems = []
    for doc in documents(root):
        rel = os.path.relpath(doc, root)
        with open(doc, encoding="utf-8") as f:
            text = f.read()
        for number, line, spans, fenced, generated in lines_with_code(text):
            where = "%s:%d: " % (rel, number)
            for match in MACHINE_PATH.finditer(line):
                problems.append(where + "a path of a developer's machine (%s...): use a path in the repository, "
                                "or out/ made by a command given here" % match.group(0))
            for match in RELATIVE_UP.finditer(line):
                target = os.path.normpath(os.path.join(os.path.dirname(doc), match.group(1), match.group(2)))
                if os.path.relpath(target, root).startswith(os.pardir):
                    problems.append(where + "a path outside the repository (%s): a user's clone has nothing "
                                    "beside it" % match.group(0))
            # The words of a generated block are scripts/bench_report.py's (its tables are kept as
            # generated): issue numbers are not checked there; tests and paths are.
            for match in ([] if generated else ISSUE.finditer(line)):
                problems.append(where + "an issue number (%s): say what it was instead" % match.group(0))
            cited = set()
            for suite, name, wildcard in CITATION.findall(line):
                if suite in suites and (name or wildcard):
                    cited.add((suite, name, wildcard))
            for span in spans:
                for suite, name, wildcard in CITATION.findall(span):
                    if suite not in suites and TEST_SHAPED.match(name) and not fenced:
                        problems.append(where + "`%s.%s`: no test suite %s under test/" % (suite, name, suite))
                for match in REPO_PATH.finditer(span):
                    if not path_exists(root, match.group(0)):
                        problems.append(where + "`%s` does not exist in the repository" % match.group(0).rstrip(".,;:)"))
                if not fenced:
                    for match in BARE_SOURCE.finditer(span):
                        name = match.group(0)
                        if name not in basenames and not any(c in name for c in "*<{$"):
                            problems.append(where + "`%s`: no such file in the repository" % name)
            for suite, name, wildcard in sorted(cited):
                if wildcard:
                    if not any(s == suite and n.startswith(name) for s, n in tests):
                        problems.append(where + "%s.%s%s: no test of suite %s starts so under test/"
                                        % (suite, name, wildcard, suite))
                elif (suite, name) not in tests:
                    problems.append(where + "%s.%s: no TEST(%s, %s) under test/" % (suite, name, suite, name))
    return problems


def main():
    root = repository_root()
    if not os.path.isdir(os.path.join(root, "test")):
        sys.stderr.write("check_docs: %s has no test/ folder\n" % root)
        return 2
    problems = check(root)
    for problem in problems:
        print(problem)
    if problems:
        print("check_docs: %d problem(s) in README.md and docs/ (docs/notebook/ is frozen and not checked)"
              % len(problems))
        return 1
    print("check_docs: every cited test and path exists; no machine paths, no issue numbers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
