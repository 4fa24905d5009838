#!/usr/bin/env python3
"""Which sources to compile alone in a unity build (FIGMENT_UNITY_BUILD): in each group of
sources that share a target, the file-local names (anonymous namespace, static, namespace-scope
constants) that more than one source defines, and the fewest sources to leave out of the batches
so that no two batched sources share one. A shared type or constant is a compile error in a
batch; two helpers of one name but different parameters would silently overload, which is why
a shared function name counts too. A rough reading of the text, not a compiler: when a batch
still fails to compile, mark the source it names as well.

    python3 scripts/unity-clashes.py sim/body/*.cpp          one target's sources
    python3 scripts/unity-clashes.py --by-module tests       the test modules (tests/<module>/)
"""
import collections
import pathlib
import re
import sys

def scan(path):
    text = open(path).read()
    text = re.sub(r'//[^\n]*', '', text)
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\])*"', '""', text)
    names = set()
    depth = 0; anon_depths = []; i = 0
    # track anonymous namespace regions
    tokens = re.finditer(r'namespace\s*\{|[{}]', text)
    regions = []; stack = []
    for m in tokens:
        t = m.group(0)
        if t.startswith('namespace'):
            stack.append(('anon', m.end()))
        elif t == '{':
            stack.append(('other', m.end()))
        else:
            if stack:
                kind, start = stack.pop()
                if kind == 'anon': regions.append((start, m.start(), len(stack)))
    for start, end, lvl in regions:
        body = text[start:end]
        # depth-0 declarations inside the region
        d = 0; buf = []
        for ch in body:
            if ch == '{': d += 1
            if d == 0: buf.append(ch)
            if ch == '}': d -= 1; buf.append(';') if d == 0 else None
        top = ''.join(buf)
        for m in re.finditer(r'([A-Za-z_]\w*)\s*\([^;{}]*\)\s*(const)?\s*(noexcept)?\s*(->[^;{}]*)?;', top):
            names.add(m.group(1))
        for m in re.finditer(r'\b(struct|class|enum|using)\s+(class\s+)?([A-Za-z_]\w*)', top):
            names.add(m.group(3))
        for m in re.finditer(r'\b([A-Za-z_]\w*)\s*(\[[^\]]*\])?\s*=\s*[^;]*;', top):
            names.add(m.group(1))
        for m in re.finditer(r'\b(?:constexpr|const|inline)\b[^;=(]*?\b([A-Za-z_]\w*)\s*(\[[^\]]*\])?\s*;', top):
            names.add(m.group(1))  # brace-initialised: constexpr Size kSize{200, 200};
    for m in re.finditer(r'^static\s+[^;{(]*?\b([A-Za-z_]\w*)\s*\(', text, re.M):
        names.add(m.group(1))
    for m in re.finditer(r'^(?:static\s+)?constexpr\s+[^;=(]*?\b([A-Za-z_]\w*)\s*=', text, re.M):
        names.add(m.group(1))
    names -= {'if','for','while','switch','return','operator','sizeof','static_assert'}
    return names


# gtest's macros and a namespace name read as definitions; PrintTo overloads by type on purpose.
NOISE = {'TEST', 'TEST_F', 'TEST_P', 'INSTANTIATE_TEST_SUITE_P', 'figment', 'PrintTo', 'test'}


def greedy(files):
    where = collections.defaultdict(set)
    for f in files:
        for n in scan(f) - NOISE: where[n].add(f)
    dup = {n: fs for n, fs in where.items() if len(fs) > 1}
    excluded = set()
    while True:
        live = {n: fs - excluded for n, fs in dup.items() if len(fs - excluded) > 1}
        if not live: return excluded
        count = collections.Counter(f for fs in live.values() for f in fs)
        excluded.add(max(sorted(count), key=lambda f: count[f]))  # the first name of the most shared


def report(name, files):
    where = collections.defaultdict(list)
    for f in files:
        for n in scan(f) - NOISE:
            where[n].append(f)
    shared = {n: fs for n, fs in where.items() if len(fs) > 1}
    alone = sorted(greedy(files))
    print(f"{name}: {len(files)} sources, {len(shared)} shared names, {len(alone)} to compile alone")
    for n, fs in sorted(shared.items()):
        print(f"  {n}: {' '.join(fs)}")
    for f in alone:
        print(f"  alone: {f}")


def main():
    args = sys.argv[1:]
    if args[:1] == ["--by-module"]:
        root = pathlib.Path(args[1])
        for module in sorted(p for p in root.iterdir() if p.is_dir()):
            files = sorted(str(f) for f in module.rglob("test_*.cpp"))
            if files:
                report(str(module), files)
    else:
        report("sources", args)


if __name__ == "__main__":
    main()
