#!/usr/bin/env python3
"""The source tree against docs/architecture.md, which is the one list of folders and layers.

Fails (exit 1, every finding printed) when
  - a folder of solver/ or server/ holding source files is not in the architecture page's folder
    table, or the table names a folder that does not exist;
  - a folder holds more than 30 source files (.cpp, .hpp, .h);
  - a source file includes a header of another folder that its folder's row does not allow
    ("may include"), or a header that does not exist;
  - a .cpp file of solver/ or server/ is in no CMakeLists.txt (it would not be built);
  - a folder of tests/solver or tests/io mirrors no source folder.

Run: python3 tests/layout/check_layout.py [--root REPOSITORY]
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {'.cpp', '.hpp', '.h'}
MAX_FILES = 30
ROW = re.compile(r'^\|\s*`((?:solver|server)(?:/[a-z_]+)*)/?`\s*\|(.*)\|(.*)\|\s*$')
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def folder_table(architecture: pathlib.Path):
    """{folder: set of folders it may include} from the rows | `folder` | holds | may include |."""
    table = {}
    for line in architecture.read_text().splitlines():
        m = ROW.match(line)
        if not m:
            continue
        allowed = set(re.findall(r'`([a-z_/]+?)/?`', m.group(3)))
        table[m.group(1)] = allowed
    return table


def include_target(root: pathlib.Path, source: pathlib.Path, name: str):
    """The folder (relative to root) of the header an include names, or None when it is not ours."""
    candidates = [root / name, root / 'server' / name, source.parent / name]
    for c in candidates:
        if c.is_file():
            return c.parent.relative_to(root).as_posix()
    return None


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('--root', default=str(pathlib.Path(__file__).resolve().parents[2]))
    root = pathlib.Path(parser.parse_args().root)
    findings = []
    table = folder_table(root / 'docs' / 'architecture.md')
    if not table:
        findings.append('docs/architecture.md has no folder table (rows | `solver/...` | holds | may include |)')

    folders = {}
    for top in ('solver', 'server'):
        for f in sorted((root / top).rglob('*')):
            if f.is_file() and (f.suffix in SOURCE_SUFFIXES or f.parent.name == 'web'):
                folders.setdefault(f.parent.relative_to(root).as_posix(), []).append(f)
    for folder, files in sorted(folders.items()):
        if folder not in table:
            findings.append(f'{folder}/ holds {files[0].name} but is in no row of docs/architecture.md')
        count = sum(1 for f in files if f.suffix in SOURCE_SUFFIXES)
        if count > MAX_FILES:
            findings.append(f'{folder}/ holds {count} source files (at most {MAX_FILES}: split it by concept)')
    for folder in sorted(table):
        if not (root / folder).is_dir():
            findings.append(f'docs/architecture.md names {folder}/, which does not exist')

    for folder, files in sorted(folders.items()):
        allowed = table.get(folder, set())
        for f in files:
            if f.suffix not in SOURCE_SUFFIXES:
                continue
            for name in INCLUDE.findall(f.read_text()):
                target = include_target(root, f, name)
                rel = f.relative_to(root).as_posix()
                if target is None:
                    if name.startswith(('solver/', 'io/', 'plot/', 'service/', 'cli/', 'web/')) and name != 'web/web_assets.hpp':
                        findings.append(f'{rel}: includes "{name}", which is not in the tree')
                    continue
                if target == folder or any(target == a or target.startswith(a + '/') for a in allowed):
                    continue
                findings.append(f'{rel}: includes "{name}" ({target}/), which {folder}/ may not include')

    cmake_text = '\n'.join(p.read_text() for p in root.rglob('CMakeLists.txt') if 'build' not in p.parts)
    for top in ('solver', 'server'):
        for f in sorted((root / top).rglob('*.cpp')):
            rel = f.relative_to(root / top).as_posix()
            if rel not in cmake_text and f.relative_to(root).as_posix() not in cmake_text:
                findings.append(f'{f.relative_to(root).as_posix()} is in no CMakeLists.txt')

    for tier, source in (('tests/solver', 'solver'), ('tests/io', 'server/io')):
        for d in sorted((root / tier).iterdir()):
            if d.is_dir() and d.name != 'data' and not (root / source / d.name).is_dir():
                findings.append(f'{d.relative_to(root).as_posix()}/ mirrors no folder of {source}/')

    for line in findings:
        print(line)
    print(f'{len(folders)} folders, {sum(len(v) for v in folders.values())} files checked; {len(findings)} findings')
    return 1 if findings else 0


if __name__ == '__main__':
    sys.exit(main())
