#!/usr/bin/env python3
"""docs/interfaces.md's layer table against CMake's link graph (ctest lint.LayerTableMatchesTheLinks).

The table's rows name a folder (`sim/core`, `io/`) and what it "depends on": FIGMENT's folders
among other names (Eigen, Coin, assimp: not checked here). A folder token names a top folder
(io, nodes, ..., sim: every sim/ folder) or, failing that, sim/<token>; "(nodes)" counts as
nodes. The link graph is the configure's figment-links.txt (cmake/FigmentLinkGraph.cmake):
each FIGMENT target, its folder and what it links. Findings, one line each:
  - a link from one folder's target to another folder's that the table does not allow;
  - a folder with targets and no row;
  - a folder a row allows that none of its targets links (the table says more than the code).

  scripts/check-layers.py BUILD_DIR [ROOT]   (exit 1 on a finding)
  scripts/check-layers.py --self-test        (the rules on samples)
"""
import pathlib
import re
import sys

TOP_FOLDERS = {"sim", "io", "nodes", "guard", "headless", "session", "viewer", "bench", "tools", "serve"}
ROW = re.compile(r"^\| `([a-z/]+?)/?` \| [^|]* \| ([^|]*) \|")


def folder_of_token(token):
    return token if token in TOP_FOLDERS else f"sim/{token}"


def read_table(text, sim_folders):
    """{folder: set of allowed folders} from the layer table's rows."""
    rows = {}
    for line in text.splitlines():
        match = ROW.match(line)
        if not match:
            continue
        tokens = re.findall(r"[A-Za-z0-9_]+", match.group(2))
        rows[match.group(1)] = {folder_of_token(token) for token in tokens
                                if token in TOP_FOLDERS or f"sim/{token}" in sim_folders}
    return rows


def read_graph(text, sim_folders):
    """[(folder, target, [linked FIGMENT targets])] and {target: folder}; tests/ left out."""
    entries = []
    for line in text.splitlines():
        parts = line.split(" ", 2)
        if len(parts) < 2 or not parts[1] or parts[1].split("/")[0] == "tests":
            continue
        target, folder = parts[0], parts[1]
        if folder == "sim":  # one library per folder, and figment_sim: them all (no row of its own)
            folder = "sim/" + target[len("figment_"):] if target != "figment_sim" else "sim"
        links = re.findall(r"figment(?:_|::)[A-Za-z0-9_]+", parts[2] if len(parts) > 2 else "")
        links = dict.fromkeys(link.replace("figment::", "figment_") for link in links)  # once each, in order
        entries.append((folder, target, list(links)))
    folders = {target: folder for folder, target, _ in entries}
    return [(f, t, [link for link in links if link in folders]) for f, t, links in entries], folders


def allows(allowed, folder):
    return folder in allowed or (folder.startswith("sim/") and "sim" in allowed)


def findings(table_text, graph_text, sim_folders):
    rows = read_table(table_text, sim_folders)
    entries, folders = read_graph(graph_text, sim_folders)
    used = {}
    for folder, target, links in entries:
        if folder == "sim":
            continue
        if folder not in rows:
            yield f"{folder}/: {target} is in no row of the layer table"
            continue
        for link in links:
            other = folders[link]
            if other == folder or other.startswith(folder + "/") or folder == "sim" and other.startswith("sim/"):
                continue
            if not allows(rows[folder], other):
                yield f"{target} ({folder}) links {link} ({other}): the layer table's {folder} row does not allow it"
            used.setdefault(folder, set()).update({other, "sim"} if other.startswith("sim/") else {other})
    for folder, allowed in rows.items():
        if folder not in {f for f, _, _ in entries}:
            continue
        for stale in sorted(allowed - used.get(folder, set())):
            yield f"{folder}: the layer table allows {stale}, which none of its targets links"


def self_test():
    table = ("| `sim/core` | x | Eigen | a |\n| `sim/cloth` | x | core | b |\n"
             "| `io/` | x | sim, assimp | c |\n| `nodes/` | x | io, Coin | d |\n")
    graph = ("figment_core sim Eigen3::Eigen\nfigment_cloth sim figment_core\n"
             "figment_io io figment_cloth;assimp::assimp\nfigment_nodes nodes figment_io;Coin::Coin\n"
             "figment_plain tests figment_nodes\n")
    sims = {"sim/core", "sim/cloth"}
    checks = [
        (graph, []),
        (graph.replace("figment_cloth sim figment_core", "figment_cloth sim figment_core;figment_io"),
         ["figment_cloth (sim/cloth) links figment_io (io): the layer table's sim/cloth row does not allow it"]),
        (graph + "figment_guard guard Coin::Coin\n", ["guard/: figment_guard is in no row of the layer table"]),
        (graph.replace("figment_nodes nodes figment_io;Coin::Coin", "figment_nodes nodes Coin::Coin"),
         ["nodes: the layer table allows io, which none of its targets links"]),
    ]
    failed = 0
    for sample, expected in checks:
        got = list(findings(table, sample, sims))
        if got != expected:
            print(f"self-test: expected {expected}, got {got}")
            failed += 1
    return 1 if failed else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    build = pathlib.Path(sys.argv[1])
    root = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path(__file__).resolve().parent.parent
    sim_folders = {f"sim/{path.name}" for path in (root / "sim").iterdir() if path.is_dir()}
    found = list(findings((root / "docs/interfaces.md").read_text(), (build / "figment-links.txt").read_text(),
                          sim_folders))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
