#!/usr/bin/python3
"""The flared skirt beside Newton's Style3D cloth solver, in one run (issue 42).

Both drape scenes/skirt.obj onto the MakeHuman-based body of human.zae: Newton's
SolverStyle3D on the body's triangles at its example's 60 fps x 10 substeps, at each
--contact-ke, until its rest rule holds (or --max-time simulated), and figment-bench's
methods study on scenes/skirt.iv (radial volumes) and scenes/skirt-triangles.iv (the body's
triangles) at each --method. Rounds are interleaved (Newton, FIGMENT, Newton, ...) so the
machine's load falls on both alike; the table gives medians over the rounds.

Newton has no rest rule of its own (its cloth examples' tests check every node under
0.5 m/s), so by default (--newton-rule figment) it stops by FIGMENT's, that of
ClothSolver::endStep/atRest with the scenes' restSpeed 0.01 and restWindow 0.25: every node
slower than 10 mm/s, its displacement over the elapsed time, at every check for 0.25 s
simulated; Newton is checked at its frames' ends (1/60 s). --newton-rule 60mm keeps the
earlier note's rule: every node's velocity under 60 mm/s at one frame's end.

Both meshes come from FIGMENT itself (figment-view --export of a scene that draws the
skirt's rest mesh and the body, metres and y up, as the engine reads them). Newton's timed
part is the stepping loop only: the model, the solver's precomputation and one warm-up
frame (Warp's kernel compilation) come before it. FIGMENT's wall is the engine's own
(figment-bench methods, median of 6 drapes); its CPU is the process's user+sys with
--repeat 6 less that with --repeat 1, over 5 (the house method, docs/results.md).

Run it with the venv's Python (bench/newton/requirements.txt, CPU only):
  /usr/bin/python3 -m venv build/newton-venv
  build/newton-venv/bin/pip install --require-hashes --only-binary :all: -r bench/newton/requirements.txt
  OMP_NUM_THREADS=1 build/newton-venv/bin/python bench/newton-skirt.py [--rounds 5] [--json out.json]
      [--newton-rule figment|60mm] [--contact-ke 10 --contact-ke 1000]"""
import argparse
import collections
import contextlib
import csv
import datetime
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent

# The skirt's fabric as scenes/skirt.iv writes it: cotton 0.6 mm, 300 kg/m^3 (180 g/m^2),
# E = 1 MPa, nu = 0.3; friction 0.5; clearance 6 mm; gravity 9.81 m/s^2 down y.
THICKNESS, DENSITY, YOUNG, POISSON = 0.0006, 300.0, 1.0e6, 0.3
FRICTION, CLEARANCE, GRAVITY = 0.5, 0.006, 9.81
SCENES = {"volumes": "scenes/skirt.iv", "triangles": "scenes/skirt-triangles.iv"}
TOLERANCE_PCT = 2.0  # ClothEngine.tolerance's budget the implicit drapes are chosen within (docs/results.md)
# FIGMENT's rest rule as scenes/skirt.iv sets it (ClothSolver::endStep, atRest): every node
# slower than REST_SPEED (m/s, displacement over the elapsed time) for REST_WINDOW (s).
REST_SPEED, REST_WINDOW = 0.01, 0.25
OLD_REST_SPEED = 0.06  # the earlier note's rule: every node's velocity under 60 mm/s, once


def export_meshes(bin_dir, out_dir):
    """The skirt's rest mesh (node order of skirt.obj as MeshFile reads it) and the body's
    drawn triangles (eyes left out, as the scenes leave them out of collisions)."""
    scene = out_dir / "meshes.iv"
    scene.write_text(
        "#Inventor V2.1 ascii\nSeparator {\n"
        '  MeshFile { fileName "human.zae" exclude "human-highpolyeyesMesh" }\n'
        f'  Switch {{ whichChild -1  DEF SkirtPattern MeshFile {{ fileName "{ROOT / "scenes/skirt.obj"}" }} }}\n'
        "  Coordinate3 { point = USE SkirtPattern.point }\n"
        "  ClothingLayer { coordIndex = USE SkirtPattern.coordIndex }\n}\n")
    obj = out_dir / "meshes.obj"
    subprocess.run([str(bin_dir / "figment-view"), str(scene), "--export", str(obj), "--export-body"], check=True,
                   stdout=subprocess.DEVNULL)
    points, groups, group = [], {}, None
    for line in obj.read_text().splitlines():
        if line.startswith("v "):
            points.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("g "):
            group = line.split()[1]
            groups[group] = []
        elif line.startswith("f "):
            groups[group].append([int(c.split("/")[0]) - 1 for c in line.split()[1:]])
    points = np.array(points)

    def mesh(faces):
        faces = np.array([f for f in faces if len(f) == 3])
        used = np.unique(faces)  # the garment's nodes are one block, in their order
        number = np.full(len(points), -1)
        number[used] = np.arange(len(used))
        return points[used], number[faces]

    garments = [g for g in groups if g.startswith("garment")]
    bodies = [g for g in groups if not g.startswith("garment")]
    skirt = mesh(groups[garments[0]])
    body = mesh([f for g in bodies for f in groups[g]])
    return skirt, body


def panel_triangles(vertices, faces):
    """Newton's Style3D reads a cloth's rest shape from flat panels: each triangle laid flat
    on its own, u along the skirt's circumference (horizontal), v up its side, so the
    stretch's warp and weft are the cone's and every triangle keeps its 3D lengths."""
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1)[:, None]
    u = np.cross(n, [0.0, 1.0, 0.0])
    flat = np.linalg.norm(u, axis=1) < 1e-6
    u[flat] = np.cross(n[flat], [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u, axis=1)[:, None]
    v = np.cross(n, u)
    panel = np.zeros((len(faces), 3, 2))
    for k, p in enumerate((a, b, c)):
        panel[:, k, 0] = ((p - a) * u).sum(axis=1)
        panel[:, k, 1] = ((p - a) * v).sum(axis=1)
    return panel.reshape(-1, 2), np.arange(3 * len(faces))


class NewtonSkirt:
    """The skirt on the body's triangles in Newton's Style3D solver, at the settings of its
    cloth example (60 fps, 10 substeps, 4 nonlinear iterations) where the scene sets none."""

    def __init__(self, skirt, body, args, contact_ke):
        import newton
        import warp as wp
        from newton.solvers import style3d

        self.wp, self.args = wp, args
        vertices, faces = skirt
        builder = newton.ModelBuilder(up_axis=newton.Axis.Y, gravity=(0.0, -GRAVITY, 0.0))
        newton.solvers.SolverStyle3D.register_custom_attributes(builder)
        # Bending: Bergou's quadratic energy 1/2 k x^T Q x approximates 1/2 k (k1 + k2)^2 per
        # area, FIGMENT's plate 1/2 D (k1 + k2)^2: k = D (an isotropic edge_ke, no aniso).
        builder.default_edge_ke = YOUNG * THICKNESS**3 / (12.0 * (1.0 - POISSON**2))
        panel, panel_indices = panel_triangles(vertices, faces)
        membrane = YOUNG * THICKNESS
        style3d.add_cloth_mesh(
            builder, pos=wp.vec3(0.0, 0.0, 0.0), rot=wp.quat_identity(), vel=wp.vec3(0.0, 0.0, 0.0),
            vertices=vertices.tolist(), indices=faces.reshape(-1).tolist(), panel_verts=panel.tolist(),
            panel_indices=panel_indices.tolist(), density=DENSITY * THICKNESS, particle_radius=CLEARANCE,
            # Baraff & Witkin stretch (no Poisson coupling): warp and weft E h (a strip's uniaxial
            # stiffness), shear G h = E h / 2(1 + nu).
            tri_aniso_ke=wp.vec3(membrane, membrane, membrane / (2.0 * (1.0 + POISSON))))
        shape = newton.ModelBuilder.ShapeConfig(mu=FRICTION, margin=0.0)
        builder.add_shape_mesh(body=-1, mesh=newton.Mesh(body[0].astype(np.float32), body[1].reshape(-1)),
                               cfg=shape)
        self.model = builder.finalize(device="cpu")
        # mu: sqrt(particle mu x shape mu) = 0.5; the contact spring the example's 10 N/m or
        # another --contact-ke, its damping the example's.
        self.model.soft_contact_mu = FRICTION
        self.model.soft_contact_ke = contact_ke
        self.model.soft_contact_kd = 1.0e-5
        self.solver = newton.solvers.SolverStyle3D(self.model, config=newton.solvers.SolverStyle3D.Config(
            iterations=args.iterations))
        self.pipeline = newton.CollisionPipeline(self.model)
        self.contacts = self.pipeline.contacts()
        self.rest = vertices

    def run(self, frames):
        """Steps up to `frames` frames, checking the rest rule at each frame's end; returns
        the frames, wall and CPU s, whether the rule held, the fastest node's speed at the
        last frame (displacement over the frame's time, m/s), each node's displacement over
        the last simulated second (or all of it, if shorter) and the final positions."""
        wp = self.wp
        state_0, state_1, control = self.model.state(), self.model.state(), self.model.control()
        fps, substeps = self.args.fps, self.args.substeps
        dt = 1.0 / fps / substeps
        figment_rule = self.args.newton_rule == "figment"
        # ClothSolver::atRest: time - restSince >= window, restSince the end of the first slow
        # check; in frames, 15 frames after the first slow one at 60 fps.
        window_frames = int(np.ceil(REST_WINDOW * fps - 1e-9))
        history = collections.deque([state_0.particle_q.numpy().astype(float)], maxlen=fps + 1)
        rested, slow_since, frame, fastest = False, None, 0, float("inf")
        wall, cpu = time.perf_counter(), time.process_time()
        while frame < frames:
            self.pipeline.collide(state_0, self.contacts)
            for _ in range(substeps):
                state_0.clear_forces()
                self.solver.step(state_0, state_1, control, self.contacts, dt)
                state_0, state_1 = state_1, state_0
            frame += 1
            positions = state_0.particle_q.numpy().astype(float)
            fastest = np.linalg.norm(positions - history[-1], axis=1).max() * fps
            history.append(positions)
            if figment_rule:
                if fastest < REST_SPEED:
                    if slow_since is None:
                        slow_since = frame
                else:
                    slow_since = None
                rested = slow_since is not None and frame - slow_since >= window_frames
            else:
                rested = np.linalg.norm(state_0.particle_qd.numpy(), axis=1).max() < OLD_REST_SPEED
            if rested:
                break
        wp.synchronize()
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        last_second = np.linalg.norm(history[-1] - history[0], axis=1)
        return frame, wall, cpu, rested, fastest, last_second, history[-1]


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def figment_methods(bench, scene, method, reference, repeat, out_dir):
    """One figment-bench methods run: its CSV row for `method` and the process's CPU s."""
    before = children_cpu()
    subprocess.run([str(bench), "methods", "--scene", scene, "--method", method, "--reference", reference,
                    "--repeat", str(repeat), "--out", str(out_dir)], check=True, stdout=subprocess.DEVNULL,
                   cwd=ROOT)
    cpu = children_cpu() - before


    with open(out_dir / "methods.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["method"] == method]
    return rows[0], cpu


def figment_round(bench, scene, method, out_dir):
    """Wall (the engine's, median of 6), CPU of one drape ((6 - 1) / 5) and steps."""
    one, cpu1 = figment_methods(bench, scene, method, method, 1, out_dir)
    six, cpu6 = figment_methods(bench, scene, method, method, 6, out_dir)
    return {"wall": float(six["median_wall_s"]), "cpu": (cpu6 - cpu1) / 5.0, "steps": int(six["steps"]),
            "at_rest": six["at_rest"] == "1"}


def reference_positions(bench, scene, step, out_dir):
    csv_path = out_dir / "reference.csv"
    subprocess.run([str(bench), "drape", "--scene", scene, "--integrator", "IMPLICIT", "--time-step", str(step),
                    "--repeat", "1", "--out", str(out_dir), "--positions", str(csv_path)], check=True,
                   stdout=subprocess.DEVNULL, cwd=ROOT)
    rows = [line.split(",") for line in csv_path.read_text().splitlines()[1:]]
    return np.array([[float(x) for x in r[2:5]] for r in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"), help="the build folder (its bin/)")
    parser.add_argument("--rounds", type=int, default=5, help="interleaved rounds (medians over them)")
    parser.add_argument("--method", action="append", help="FIGMENT methods (default implicit:0.05, implicit:0.05:0.4)")
    parser.add_argument("--reference", default="implicit:0.01", help="FIGMENT's converged drape")
    parser.add_argument("--fps", type=int, default=60)
    parser.add_argument("--substeps", type=int, default=10)
    parser.add_argument("--iterations", type=int, default=4, help="Style3D's nonlinear iterations per substep")
    parser.add_argument("--contact-ke", type=float, action="append",
                        help="Newton's body contact stiffness, N/m; repeat for more configurations (default 10, "
                             "its example's)")
    parser.add_argument("--newton-rule", choices=["figment", "60mm"], default="figment",
                        help="Newton's rest rule: FIGMENT's (every node under 10 mm/s for 0.25 s, the default) or "
                             "the earlier note's (every node under 60 mm/s at one frame's end)")
    parser.add_argument("--max-time", type=float, default=10.0, help="Newton's simulated s before it gives up")
    parser.add_argument("--json", help="also write the results here")
    args = parser.parse_args()
    methods = args.method or ["implicit:0.05", "implicit:0.05:0.4"]
    contact_kes = args.contact_ke or [10.0]
    bin_dir = Path(args.build) / "bin"
    bench = bin_dir / "figment-bench"
    if os.environ.get("OMP_NUM_THREADS") != "1":
        sys.exit("newton-skirt: run with OMP_NUM_THREADS=1 (both on one thread)")

    load = os.getloadavg()
    import warp as wp

    # Warp and Newton log their modules' loading on stdout: stderr keeps it off the table.
    with contextlib.redirect_stdout(sys.stderr), tempfile.TemporaryDirectory() as tmp:
        wp.init()
        wp.set_device("cpu")
        import newton

        tmp = Path(tmp)
        skirt, body = export_meshes(bin_dir, tmp)
        height = skirt[0][:, 1].max() - skirt[0][:, 1].min()
        newtons = {ke: NewtonSkirt(skirt, body, args, ke) for ke in contact_kes}
        for newton_skirt in newtons.values():
            newton_skirt.run(1)  # the warm-up frame: Warp compiles (or loads) its kernels here
        frames = int(round(args.max_time * args.fps))

        # Untimed: FIGMENT's deviations from its converged drape, and that drape's nodes.
        deviation, references = {}, {}
        for name, scene in SCENES.items():
            subprocess.run([str(bench), "methods", "--scene", scene, *sum((["--method", m] for m in methods), []),
                            "--reference", args.reference, "--repeat", "1", "--out", str(tmp)], check=True,
                           stdout=subprocess.DEVNULL, cwd=ROOT)


            with open(tmp / "methods.csv") as f:
                for r in csv.DictReader(f):
                    deviation[(name, r["method"])] = float(r["mean_dev_pct_height"])
            references[name] = reference_positions(bench, scene, float(args.reference.split(":")[1]), tmp)

        runs, figment_runs, finals = {}, {}, {}
        for k in range(args.rounds):
            for ke, newton_skirt in newtons.items():
                frame, wall, cpu, rested, fastest, last_second, positions = newton_skirt.run(frames)
                runs.setdefault(ke, []).append({
                    "wall": wall, "cpu": cpu, "steps": frame * args.substeps, "frames": frame, "at_rest": rested,
                    "simulated_s": frame / args.fps, "fastest_m_s": fastest,
                    "last_second_mm": {"mean": 1000 * last_second.mean(), "max": 1000 * last_second.max()}})
                finals[ke] = positions
                print(f"round {k + 1}: Newton ke {ke:g}: {frame} frames, {wall:.2f} s wall, {cpu:.2f} s CPU, "
                      f"{'rest' if rested else 'moving'}, fastest {1000 * fastest:.1f} mm/s", file=sys.stderr)
            for name, scene in SCENES.items():
                for m in methods:
                    r = figment_round(bench, scene, m, tmp)
                    figment_runs.setdefault((name, m), []).append(r)
                    print(f"round {k + 1}: FIGMENT {name} {m}: {r['steps']} steps, {r['wall']:.3f} s wall, "
                          f"{r['cpu']:.3f} s CPU", file=sys.stderr)

    def med(rows, key):
        return statistics.median(r[key] for r in rows)

    rule = ("every node under 10 mm/s (displacement over a frame) for 0.25 s, FIGMENT's" if args.newton_rule == "figment"
            else "every node's velocity under 60 mm/s at one frame's end")
    result = {
        "date": datetime.date.today().isoformat(), "machine": f"{platform.machine()}, {os.cpu_count()} cores",
        "load_before": load, "load_after": os.getloadavg(), "newton": newton.__version__, "warp": wp.__version__,
        "newton_rule": rule, "max_time_s": args.max_time, "newton_runs": [], "figment": []}
    print(f"Newton {newton.__version__} Style3D, {args.fps} fps x {args.substeps} substeps, {args.iterations} "
          f"iterations, rest rule: {rule}, checked at frames' ends, up to {args.max_time:g} s simulated; medians of "
          f"{args.rounds}; load average {load[0]:.2f} before, {os.getloadavg()[0]:.2f} after\n")
    print("| Newton, contact ke | frames (substeps) | simulated s | rule | wall s | CPU s | fastest node over the last "
          "frame, mm/s | from FIGMENT's reference, volumes / triangles: mean, max mm (% height) | moved over the last "
          "simulated s (or all, if less): mean, max mm |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    newton_time = {}
    for ke, rows in runs.items():
        last = rows[-1]
        if len({r["frames"] for r in rows}) > 1:
            print(f"  (ke {ke:g}: frames differ between rounds: {[r['frames'] for r in rows]})")
        apart = {name: np.linalg.norm(finals[ke] - ref, axis=1) for name, ref in references.items()}
        nw, nc = med(rows, "wall"), med(rows, "cpu")
        newton_time[ke] = (nw, nc)
        bound = "" if last["at_rest"] else "≥ "
        result["newton_runs"].append({
            "contact_ke": ke, "wall_s": nw, "cpu_s": nc, "substeps": last["steps"], "frames": last["frames"],
            "simulated_s": last["simulated_s"], "at_rest": last["at_rest"], "fastest_m_s": last["fastest_m_s"],
            "last_second_mm": last["last_second_mm"],
            "from_reference": {name: {"mean_mm": 1000 * d.mean(), "max_mm": 1000 * d.max(),
                                      "mean_pct_height": 100 * d.mean() / height,
                                      "max_pct_height": 100 * d.max() / height} for name, d in apart.items()}})
        far = " / ".join(f"{1000 * d.mean():.0f}, {1000 * d.max():.0f} ({100 * d.mean() / height:.1f} %, "
                         f"{100 * d.max() / height:.0f} %)" for d in apart.values())
        print(f"| {ke:g} N/m | {last['frames']} ({last['steps']}) | {bound}{last['simulated_s']:.2f} | "
              f"{'rest' if last['at_rest'] else 'moving at the bound'} | {bound}{nw:.2f} | {bound}{nc:.2f} | "
              f"{1000 * last['fastest_m_s']:.1f} | {far} | {last['last_second_mm']['mean']:.1f}, "
              f"{last['last_second_mm']['max']:.1f} |")
    heads = " | ".join(f"Newton (ke {ke:g}) / FIGMENT wall, CPU" for ke in runs)
    print(f"\n| FIGMENT | steps | rest | wall s | CPU s | deviation (budget {TOLERANCE_PCT} %) | {heads} |")
    print("| --- | --- | --- | --- | --- | --- |" + " --- |" * len(runs))
    for name in SCENES:
        for m in methods:
            rows = figment_runs[(name, m)]
            w, c = med(rows, "wall"), med(rows, "cpu")
            ratios = {ke: (nw / w, nc / c) for ke, (nw, nc) in newton_time.items()}
            row = {"scene": name, "method": m, "steps": rows[-1]["steps"], "at_rest": rows[-1]["at_rest"],
                   "wall_s": w, "cpu_s": c, "dev_pct_height": deviation[(name, m)],
                   "ratio_wall_cpu": {str(ke): r for ke, r in ratios.items()}}
            result["figment"].append(row)
            cells = " | ".join(f"{'≥ ' if not runs[ke][-1]['at_rest'] else ''}{a:.1f}x, {b:.1f}x"
                               for ke, (a, b) in ratios.items())
            print(f"| {name} {m} | {row['steps']} | {'yes' if row['at_rest'] else 'no'} | {w:.3f} | {c:.3f} | "
                  f"{row['dev_pct_height']:.2f} % | {cells} |")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=2) + "\n")


if __name__ == "__main__":
    main()
