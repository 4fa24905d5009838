#!/usr/bin/env python3
"""figment-view against randomly mutated copies of the shipped small scenes.

Each input is a scene of scenes/examples/ or scenes/hybrid/ with 1 to 4 random edits
(a token inserted, a span deleted, a span copied elsewhere). figment-view must either
render it (exit 0) or fail with exactly one line on stderr and exit 1 or 2, within the
time limit. Anything else (a signal, several lines, a hang) is printed and counted.

    scripts/mutation-check.py [--count 1000] [--seed 1] [--viewer build/bin/figment-view]

Exit status: 0 when every input behaved, 1 otherwise. Inputs that misbehaved are kept
in the work folder it names.
"""
import argparse
import pathlib
import random
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
TOKENS = ['{', '}', '[', ']', '0', '-1', '1e9', 'nan', 'USE', 'DEF', '"', '#', 'Separator',
          'ClothEngine', '2147483647', ',', '.', '=', 'File', 'TRUE', '-0.0', '1e-30', '\n']


def mutate(text: str, rng: random.Random) -> str:
    for _ in range(rng.randint(1, 4)):
        at = rng.randrange(len(text))
        kind = rng.randrange(3)
        if kind == 0:
            text = text[:at] + rng.choice(TOKENS) + text[at:]
        elif kind == 1:
            text = text[:at] + text[at + rng.randint(1, 20):]
        else:
            source = rng.randrange(len(text))
            text = text[:at] + text[source:source + rng.randint(1, 30)] + text[at:]
    return text


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--count', type=int, default=1000)
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--viewer', default=str(ROOT / 'build/bin/figment-view'))
    parser.add_argument('--timeout', type=float, default=60.0, help='seconds an input may take')
    args = parser.parse_args()

    scenes = sorted(p for folder in ('scenes/examples', 'scenes/hybrid')
                    for p in (ROOT / folder).glob('*.iv') if p.stat().st_size < 20000)
    rng = random.Random(args.seed)
    work = pathlib.Path(tempfile.mkdtemp(prefix='figment-mutation-'))
    bad = 0
    for i in range(args.count):
        scene = rng.choice(scenes)
        path = work / f'{i}.iv'
        path.write_text(mutate(scene.read_text(), rng))
        image = work / f'{i}.png'
        try:
            # From the examples' folder: their includes resolve as they do for the originals.
            run = subprocess.run([args.viewer, str(path), '-o', str(image), '--size', '64x64', '--no-cache'],
                                 capture_output=True, text=True, errors='replace', timeout=args.timeout,
                                 cwd=scene.parent)
            lines = [line for line in run.stderr.splitlines() if line.strip()]
            failed_well = run.returncode in (1, 2) and len(lines) == 1 and not image.exists()
            if run.returncode != 0 and not failed_well:
                bad += 1
                print(f'{path} (from {scene.name}): exit {run.returncode}, {len(lines)} lines: {run.stderr[:300]!r}')
                continue
        except subprocess.TimeoutExpired:
            bad += 1
            print(f'{path} (from {scene.name}): still running after {args.timeout:g} s')
            continue
        path.unlink()
        image.unlink(missing_ok=True)
    print(f'{args.count} mutated scenes, {bad} misbehaved' + (f' (kept in {work})' if bad else ''))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
