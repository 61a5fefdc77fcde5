#!/usr/bin/python3
"""`granwave export` writes what the field's readers open: a run file (the fixture's short run of
the paper's dry scene) is exported in FORMAT, every 10th frame, and read back by READER, which
must find the run file's frames (read with h5py):
  extxyz ase           positions, velocities, angular velocities, cell and time, bit for bit
  extxyz mdanalysis    positions to float32 (MDAnalysis's XYZ reader reads no more)
  gsd gsd              gsd.hoomd: step, box, N, type, mass, diameter, positions and velocities
                       (container frame, float32, bit for bit), time, plate height and
                       angular velocities (float64, bit for bit); the file layer's header;
                       the pure-Python reader gsd.pygsd too
  gsd mdanalysis       MDAnalysis's GSD reader: frames, steps, box, positions, masses
  lammps-dump ase      ase.io lammps-dump-text with units="si": positions, velocities, cell,
                       its origin (the plate) and periodicity, converted to ASE's units
  lammps-dump mdanalysis  LAMMPSDUMP reader: steps, box, positions (relative to the box's
                       lower corner, as MDAnalysis puts them) and velocities, to float32
  h5md mdanalysis      Universe("x.h5md") with no other argument: positions, velocities,
                       box and time converted by MDAnalysis from the file's units, the plate
                       height as an observable
Usage: export_in_readers.py FORMAT READER GRANWAVE RUN.h5 WORKDIR
Exit 0 if all agree, 77 (skipped) if the reader's Debian package is not installed, else 1."""
import os
import subprocess
import sys
import warnings

import h5py
import numpy as np

fmt, reader, granwave, run_path, workdir = sys.argv[1:6]
module, package = {"ase": ("ase.io", "python3-ase"), "gsd": ("gsd.hoomd", "python3-gsd"),
                   "mdanalysis": ("MDAnalysis", "python3-mdanalysis")}[reader]
try:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        __import__(module)
except ImportError:
    print(f"export_in_readers: skipped: {reader} is not installed (apt-get install {package})")
    sys.exit(77)

EVERY = 10
G = "/particles/all/"


class Run:
    """The run file's frames that the export holds, as float64 arrays [frames][N]."""

    def __init__(self, f):
        n = f[G + "position/value"].shape[0]
        self.k = list(range(0, n, EVERY))
        pos, vel = f[G + "position/value"][self.k], f[G + "velocity/value"][self.k]
        self.x, self.z, self.vx, self.vz = pos[:, :, 0], pos[:, :, 2], vel[:, :, 0], vel[:, :, 2]
        self.spin = f[G + "angular_velocity/value"][self.k]
        self.step = f[G + "position/step"][self.k]
        self.time = f[G + "position/time"][self.k]
        edges = f[G + "box/edges/value"][0]
        self.lx, self.d, self.lz = edges[0, 0], edges[1, 1], edges[2, 2]
        plate = dict(zip(f["/observables/plate_height/step"][:],
                         f["/observables/plate_height/value"][:]))
        self.plate = np.array([plate[s] for s in self.step])
        self.pbc = [b == b"periodic" or b == "periodic" for b in f[G + "box"].attrs["boundary"]]
        self.n = pos.shape[1]


class Check:
    def __init__(self):
        self.problems = []

    def equal(self, what, got, want):
        if got is None or np.shape(got) != np.shape(want) or not np.array_equal(got, want):
            self.problems.append(f"{what} differ")

    def close(self, what, got, want, rtol=0.0, atol=0.0):
        if got is None or np.shape(got) != np.shape(want) or \
                not np.allclose(got, want, rtol=rtol, atol=atol):
            self.problems.append(f"{what} differ (largest difference "
                                 f"{np.max(np.abs(np.asarray(got) - want)) if got is not None else '-'})")

    def frames(self, got, run):
        if got != len(run.k):
            self.problems.append(f"{got} frames, {len(run.k)} expected")
            return False
        return True


def f32(a):
    return np.asarray(a, dtype=np.float64).astype(np.float32)


def extxyz_ase(path, run, c):
    import ase
    import ase.io
    frames = ase.io.read(path, index=":")
    if c.frames(len(frames), run):
        for i, a in enumerate(frames):
            zero = np.zeros(run.n)
            c.equal(f"frame {i} positions", a.positions, np.stack([run.x[i], zero, run.z[i]], 1))
            c.equal(f"frame {i} velocities", a.arrays.get("velocities"),
                    np.stack([run.vx[i], zero, run.vz[i]], 1))
            c.equal(f"frame {i} angular velocities", a.arrays.get("angular_velocity"), run.spin[i])
            c.equal(f"frame {i} cell", a.cell.lengths(), [run.lx, run.d, run.lz])
            c.equal(f"frame {i} time", a.info.get("Time"), run.time[i])
    return f"ASE {ase.__version__}"


def extxyz_mdanalysis(path, run, c):
    import MDAnalysis
    u = MDAnalysis.Universe(path, format="XYZ", topology_format="XYZ")
    if c.frames(len(u.trajectory), run):
        for i, _ in enumerate(u.trajectory):
            c.equal(f"frame {i} positions", u.atoms.positions,
                    f32(np.stack([run.x[i], np.zeros(run.n), run.z[i]], 1)))
    return f"MDAnalysis {MDAnalysis.__version__}"


def gsd_position(run, i):
    return np.stack([f32(run.x[i] - 0.5 * run.lx), np.zeros(run.n, np.float32),
                     f32(run.z[i] - (run.plate[i] + 0.5 * run.lz))], 1)


def gsd_gsd(path, run, c):
    import gsd
    import gsd.fl
    import gsd.hoomd
    with gsd.fl.open(name=path, mode="rb") as f:
        header = (tuple(f.gsd_version), f.schema, tuple(f.schema_version))
        if header != ((2, 0), "hoomd", (1, 4)) or not f.application.startswith("granwave "):
            c.problems.append(f"header {header}, application {f.application}")
    # gsd's pure-Python reader checks the index and namelist on its own.
    import gsd.pygsd
    with open(path, "rb") as raw, gsd.pygsd.GSDFile(raw) as f:
        pure = gsd.hoomd.HOOMDTrajectory(f)
        c.equal("frames (pure-Python reader)", len(pure), len(run.k))
        c.equal("last frame's positions (pure-Python reader)", pure[-1].particles.position,
                gsd_position(run, len(run.k) - 1))
    with gsd.hoomd.open(path, mode="rb") as t:
        if not c.frames(len(t), run):
            return f"gsd {gsd.__version__}"
        for i, s in enumerate(t):
            zero = np.zeros(run.n, np.float32)
            c.equal(f"frame {i} step", s.configuration.step, run.step[i])
            c.equal(f"frame {i} box", s.configuration.box, f32([run.lx, run.d, run.lz, 0, 0, 0]))
            if (s.particles.N, s.particles.types) != (run.n, ["disk"]):
                c.problems.append(f"frame {i}: N, types {s.particles.N}, {s.particles.types}")
            c.equal(f"frame {i} diameters", s.particles.diameter, f32(np.full(run.n, run.d)))
            c.equal(f"frame {i} positions", s.particles.position, gsd_position(run, i))
            c.equal(f"frame {i} velocities", s.particles.velocity,
                    np.stack([f32(run.vx[i]), zero, f32(run.vz[i])], 1))
            c.equal(f"frame {i} time", s.log["time"], [run.time[i]])
            c.equal(f"frame {i} plate height", s.log["plate_height"], [run.plate[i]])
            c.equal(f"frame {i} angular velocities", s.log["particles/angular_velocity"],
                    run.spin[i])
        # mass: rho pi d^3 / 6 of the scene's glass disks
        c.close("masses", t[0].particles.mass, f32(np.full(run.n, 2580 * np.pi * run.d**3 / 6)),
                rtol=1e-6)
    return f"gsd {gsd.__version__}"


def gsd_mdanalysis(path, run, c):
    import MDAnalysis
    u = MDAnalysis.Universe(path)
    if c.frames(len(u.trajectory), run):
        for i, ts in enumerate(u.trajectory):
            c.equal(f"frame {i} step", ts.data["step"], run.step[i])
            c.equal(f"frame {i} box", ts.dimensions, f32([run.lx, run.d, run.lz, 90, 90, 90]))
            c.equal(f"frame {i} positions", u.atoms.positions, gsd_position(run, i))
    c.close("masses", u.atoms.masses, np.full(run.n, 2580 * np.pi * run.d**3 / 6), rtol=1e-6)
    return f"MDAnalysis {MDAnalysis.__version__}"


def lammps_ase(path, run, c):
    import ase
    import ase.io
    from ase.calculators.lammps import convert
    frames = ase.io.read(path, format="lammps-dump-text", index=":", units="si")
    metre = convert(1.0, "distance", "si", "ASE")  # 1e10: ASE's lengths are Angstrom
    if c.frames(len(frames), run):
        for i, a in enumerate(frames):
            zero = np.zeros(run.n)
            c.close(f"frame {i} positions", a.positions / metre,
                    np.stack([run.x[i], zero, run.z[i]], 1), rtol=1e-15)
            c.close(f"frame {i} velocities", convert(a.get_velocities(), "velocity", "ASE", "si"),
                    np.stack([run.vx[i], zero, run.vz[i]], 1), rtol=1e-13, atol=1e-300)
            c.close(f"frame {i} cell", a.cell.lengths() / metre, [run.lx, run.d, run.lz],
                    rtol=1e-15)
            c.close(f"frame {i} cell origin", np.ravel(a.get_celldisp()) / metre,
                    [0, -0.5 * run.d, run.plate[i]], rtol=1e-15, atol=1e-300)
            c.equal(f"frame {i} periodicity", list(a.pbc), run.pbc)
    return f"ASE {ase.__version__}"


def lammps_mdanalysis(path, run, c):
    import MDAnalysis
    u = MDAnalysis.Universe(path, format="LAMMPSDUMP")
    if c.frames(len(u.trajectory), run):
        for i, ts in enumerate(u.trajectory):
            c.equal(f"frame {i} step", ts.data["step"], run.step[i])
            c.close(f"frame {i} box", ts.dimensions, [run.lx, run.d, run.lz, 90, 90, 90],
                    rtol=1e-7)
            # MDAnalysis moves the box's lower corner to the origin; float32 throughout.
            c.close(f"frame {i} positions", u.atoms.positions,
                    np.stack([run.x[i], np.full(run.n, 0.5 * run.d), run.z[i] - run.plate[i]], 1),
                    atol=2e-8)
            c.close(f"frame {i} velocities", u.atoms.velocities,
                    np.stack([run.vx[i], np.zeros(run.n), run.vz[i]], 1), rtol=1e-7, atol=1e-30)
    return f"MDAnalysis {MDAnalysis.__version__}"


def h5md_mdanalysis(path, run, c):
    import MDAnalysis
    u = MDAnalysis.Universe(path)  # the format from the extension, the topology from the file
    angstrom, per_ps = 1e10, 1e-12  # MDAnalysis's units
    if c.frames(len(u.trajectory), run):
        for i, ts in enumerate(u.trajectory):
            zero = np.zeros(run.n)
            c.equal(f"frame {i} step", ts.data["step"], run.step[i])
            c.close(f"frame {i} time", ts.time, run.time[i] / per_ps, rtol=1e-12)
            c.close(f"frame {i} box", ts.dimensions,
                    [run.lx * angstrom, run.d * angstrom, run.lz * angstrom, 90, 90, 90], rtol=1e-6)
            c.close(f"frame {i} positions", u.atoms.positions,
                    np.stack([run.x[i], zero, run.z[i]], 1) * angstrom, rtol=1e-6, atol=1.0)
            c.close(f"frame {i} velocities", u.atoms.velocities,
                    np.stack([run.vx[i], zero, run.vz[i]], 1) * angstrom * per_ps, rtol=1e-6,
                    atol=1e-30)
            c.close(f"frame {i} plate height", ts.data["plate_height"], run.plate[i] * 1e9,
                    rtol=1e-12)
    return f"MDAnalysis {MDAnalysis.__version__}"


checks = {("extxyz", "ase"): extxyz_ase, ("extxyz", "mdanalysis"): extxyz_mdanalysis,
          ("gsd", "gsd"): gsd_gsd, ("gsd", "mdanalysis"): gsd_mdanalysis,
          ("lammps-dump", "ase"): lammps_ase, ("lammps-dump", "mdanalysis"): lammps_mdanalysis,
          ("h5md", "mdanalysis"): h5md_mdanalysis}
extension = {"extxyz": ".extxyz", "gsd": ".gsd", "lammps-dump": ".lammpstrj", "h5md": ".h5md"}
os.makedirs(workdir, exist_ok=True)
out = os.path.join(workdir, f"{fmt}-{reader}{extension[fmt]}")
subprocess.run([granwave, "export", run_path, "-o", out, "--format", fmt, "--every", str(EVERY)],
               check=True, stdout=subprocess.DEVNULL)
c = Check()
with h5py.File(run_path, "r") as f, warnings.catch_warnings():
    warnings.simplefilter("ignore")
    run = Run(f)
    what = checks[(fmt, reader)](out, run, c)
if c.problems:
    print(f"export_in_readers: {fmt} in {reader}: " + "; ".join(c.problems[:5]))
    sys.exit(1)
os.remove(out)
print(f"export_in_readers: ok ({fmt} in {what}, {len(run.k)} frames)")
