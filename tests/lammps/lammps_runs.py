"""Running LAMMPS with bounce's plugin, and bounce's CLI beside it, for the validation tests
(tests/lammps, docs/lammps.md). Paths come from the environment CTest sets: BOUNCE_LMP (the
`lmp` built with PLUGIN), BOUNCE_PLUGIN (bounceplugin.so), BOUNCE_CLI (bin/bounce)."""
import json
import math
import os
import re
import subprocess
import tempfile

LMP = os.environ.get("BOUNCE_LMP", "")
PLUGIN = os.environ.get("BOUNCE_PLUGIN", "")
CLI = os.environ.get("BOUNCE_CLI", "")
last_output = ""  # head_on's last LAMMPS output


def bounce(*args):
    """`bounce collide ... --json` as a dict."""
    out = subprocess.run([CLI, "collide", *args, "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def cli_args(options):
    """{"material": "ice-bshp96", "A": 1e-5} -> ["--material", "ice-bshp96", "--A", "1e-05"]."""
    out = []
    for key, value in options.items():
        out += ["--" + key.replace("_", "-"), str(value)]
    return out


def coeff_args(options):
    """The same options as pair_coeff's key value pairs."""
    return " ".join(f"{key} {value}" for key, value in options.items())


def run_lammps(script, cores=1, check=True):
    """Runs an input script (text); returns (returncode, stdout + stderr)."""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "in.test")
        with open(path, "w") as f:
            f.write(script)
        # Line-buffered: a LAMMPS error ends in MPI_Abort, which would drop a full pipe buffer.
        command = ["stdbuf", "-oL", "-eL", LMP, "-in", path, "-log", "none"]
        if cores > 1:
            command = ["mpirun", "-np", str(cores), "--oversubscribe"] + command
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
        done = subprocess.run(command, capture_output=True, text=True, cwd=work, env=env, timeout=900)
    output = done.stdout + done.stderr
    if check and done.returncode != 0:
        raise RuntimeError(f"lmp failed ({done.returncode}):\n{output[-3000:]}")
    return done.returncode, output


def final_state(output):
    """The numbers of the last line a script printed as `print "STATE ..."`."""
    state = re.findall(r"^STATE (.*)$", output, re.M)
    if not state:
        raise RuntimeError(f"no final state in:\n{output[-3000:]}")
    return [float(v) for v in state[-1].split()]


def run_in(work, script, cores, name="in.run"):
    """Runs an input script on `cores` MPI ranks in the folder `work` (its files stay there);
    returns LAMMPS's log (log.lammps), or exits naming the failure."""
    with open(os.path.join(work, name), "w") as f:
        f.write(script)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = ["mpirun", "-np", str(cores), "--oversubscribe", LMP, "-in", name, "-log", "log.lammps"]
    done = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"lmp failed:\n{(done.stdout + done.stderr)[-3000:]}")
    with open(os.path.join(work, "log.lammps")) as f:
        return f.read()


def demo_setup(description, root, name, extra=lambda parser: None):
    """The command line of a LAMMPS demonstration (tools/hcs.py, tools/aggregation.py): --build,
    --out, --cores, --quick (and `extra`'s), the build checked and named in the environment for
    this module; out/figures and out/NAME made. Returns (args, build folder)."""
    import argparse
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--out", default=os.path.join(root, "out"))
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("--quick", action="store_true", help="a tenth of the time: a smoke run, not the result")
    extra(parser)
    args = parser.parse_args()
    if not 1 <= args.cores <= 1024:  # the project's rule: what was typed, its value, what is allowed
        parser.exit(2, f"{name}: --cores = {args.cores} is invalid: expected 1 to 1024 MPI ranks\n")
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        parser.exit(2, f"{name}: --out = {args.out} is invalid: expected a folder (it is a file)\n")
    build = os.path.abspath(args.build)
    lmp, plugin = os.path.join(build, "lammps", "lmp"), os.path.join(build, "lammps", "bounceplugin.so")
    if not (os.path.exists(lmp) and os.path.exists(plugin)):
        parser.exit(2, f"{name}: --build = {args.build} is invalid: expected a build folder with lammps/lmp and "
                       "lammps/bounceplugin.so (run `make lammps` first)\n")
    global LMP, PLUGIN, CLI
    LMP, PLUGIN, CLI = lmp, plugin, os.path.join(build, "bin", "bounce")
    os.environ.update(BOUNCE_LMP=LMP, BOUNCE_PLUGIN=PLUGIN, BOUNCE_CLI=CLI)
    for folder in ("figures", name):
        os.makedirs(os.path.join(args.out, folder), exist_ok=True)
    return args, build


def printed(output, name):
    """The number after `name` in a line LAMMPS printed ("COR 0.5486")."""
    match = re.findall(rf"^{name} (\S+)$", output, re.M)
    if not match:
        raise RuntimeError(f"no {name} in:\n{output[-3000:]}")
    return float(match[-1])


# One atom's spin as a global value: `variable w equal c_spin[1]` on a per-atom compute stops LAMMPS
# 20250204 ("Mismatched compute in variable formula"); a sum over a group of that one atom works
# on every release.


def preamble(box, types):
    """An SI sphere system in a fixed cube of half-side `box` with `types` atom types, atoms
    addressable by id (x[1], vx[2] in variables)."""
    return f"""
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block {-box} {box} {-box} {box} {-box} {box}
create_box {types} box
"""


def head_on(pair, model, velocity, steps_per_contact=1000, pair_style="bounce", coeff=None, radius2=None,
            tangential_velocity=0.0, gap=0.0, coeff_lines=None):
    """A two-sphere collision in LAMMPS: `pair` holds the bodies (material[, material2],
    radius[, radius2]) as for `bounce collide`, `model` the model's options. The spheres touch
    at t = 0 (or are `gap` apart: a contact that forms before touching) with relative normal
    speed `velocity` (and tangential `tangential_velocity`) in their centre-of-mass frame;
    dt = t_c / steps_per_contact with bounce's contact time.
    Returns (eps^N from LAMMPS, eps^T from LAMMPS, bounce's record)."""
    options = dict(pair, **model)
    extra = ["--tangential-velocity", str(tangential_velocity)] if tangential_velocity else []
    ref = bounce(*cli_args(options), "--velocity", str(velocity), *extra)
    b1, b2 = ref["pair"]["body1"], ref["pair"]["body2"]
    r1, r2, m1, m2 = b1["radius"], b2["radius"], b1["mass"], b2["mass"]
    dt = ref["contact_time"] / steps_per_contact
    approach = gap / velocity  # the flight before the gap closes
    steps = int(3 * steps_per_contact + math.ceil(approach / dt))
    box = 4 * (r1 + r2)
    v1, v2 = velocity * m2 / (m1 + m2), -velocity * m1 / (m1 + m2)
    u1, u2 = tangential_velocity * m2 / (m1 + m2), -tangential_velocity * m1 / (m1 + m2)
    materials = {k: v for k, v in pair.items() if not k.startswith("radius")}
    if coeff_lines is not None:  # pair_coeff lines as given
        coeffs = coeff_lines
    elif coeff is None:
        coeffs = pair_coeffs(materials, model)
    else:
        coeffs = "pair_coeff * * " + coeff.split(" ", 1)[1]
    plugin = f"plugin load {PLUGIN}" if pair_style.startswith("bounce") else ""
    script = preamble(box, 2) + f"""
create_atoms 1 single {-r1 - 0.5 * gap!r} 0 0
create_atoms 2 single {r2 + 0.5 * gap!r} 0 0
set atom 1 diameter {2 * r1} mass {m1}
set atom 2 diameter {2 * r2} mass {m2}
velocity all set 0 0 0
set atom 1 vx {v1!r} vy {u1!r}
set atom 2 vx {v2!r} vy {u2!r}
{plugin}
pair_style {pair_style}
{coeffs}
neighbor {max(r1, r2) * 0.1} bin
timestep {dt!r}
fix 1 all nve/sphere
group one id 1
group two id 2
compute spin all property/atom omegaz
compute w1 one reduce sum c_spin
compute w2 two reduce sum c_spin
variable w1 equal c_w1
variable w2 equal c_w2
thermo_style custom step v_w1 v_w2
thermo {steps}
run {steps}
print "STATE $(x[1]:%.17g) $(y[1]:%.17g) $(vx[1]:%.17g) $(vy[1]:%.17g) $(v_w1:%.17g) $(x[2]:%.17g) $(y[2]:%.17g) $(vx[2]:%.17g) $(vy[2]:%.17g) $(v_w2:%.17g)"
"""
    _, output = run_lammps(script)
    global last_output
    last_output = output  # what LAMMPS printed (for its warnings)
    x1, y1, vx1, vy1, w1, x2, y2, vx2, vy2, w2 = final_state(output)
    # The frame of the contact as it ended: the line of centres at separation (bounce's contact
    # time; after it the centres fly straight), not the x axis: sliding turns it by about
    # g^T t_c / (R1 + R2), which would otherwise mix g^N into g^T (BSHP96's geometry is fixed).
    flight = steps * dt - approach - ref["contact_time"]
    dx, dy = (x1 - vx1 * flight) - (x2 - vx2 * flight), (y1 - vy1 * flight) - (y2 - vy2 * flight)
    norm = math.hypot(dx, dy)
    nx, ny = dx / norm, dy / norm  # from 2 to 1 (initially -x)
    tx, ty = ny, -nx               # n x z: initially +y
    # Contact points' relative velocity: v1 + w1 z x (-R1 n) - (v2 + w2 z x (R2 n)).
    gx = (vx1 - vx2) + (w1 * r1 + w2 * r2) * ny
    gy = (vy1 - vy2) - (w1 * r1 + w2 * r2) * nx
    eps_n = (gx * nx + gy * ny) / velocity
    eps_t = (gx * tx + gy * ty) / tangential_velocity if tangential_velocity else float("nan")
    return eps_n, eps_t, ref



BODY2 = {"material2": "material", "E2": "E", "nu2": "nu", "gamma2": "gamma"}


def pair_coeffs(materials, model):
    """pair_coeff lines of pair_style bounce for atom types 1 (body 1) and 2 (body 2): each type
    with itself takes its own material (one type, one material), 1 2 takes both."""
    name = model["model"]
    rest = {k: v for k, v in model.items() if k != "model"}
    body1 = {k: v for k, v in materials.items() if k not in BODY2}
    body2 = dict(body1, **{BODY2[k]: v for k, v in materials.items() if k in BODY2})
    return "\n".join([f"pair_coeff 1 1 {name} {coeff_args(dict(body1, **rest))}",
                      f"pair_coeff 2 2 {name} {coeff_args(dict(body2, **rest))}",
                      f"pair_coeff 1 2 {name} {coeff_args(dict(materials, **rest))}"])


def order(errors, factor=2.0):
    """The convergence orders between successive errors of steps shrinking by `factor`."""
    return [math.log(abs(a) / abs(b)) / math.log(factor) for a, b in zip(errors, errors[1:])]


def gas_script(coeff, cells=22, radius=1e-3, density=1000.0, phi=0.05, speed=1.0, dt=2e-7, steps=1000, seed=4927,
               pair_style="bounce", dump=None, thermo=100, extra="", skin=None):
    """A granular gas in a periodic box: cells^3 spheres on a simple cubic lattice at volume
    fraction `phi`, Gaussian velocities of rms `speed` (no net momentum; the same on any
    number of ranks: loop geom), `steps` steps of `dt`. Thermo prints step, the kinetic energy
    and the number of contacts (pair neighbors within reach). `dump`: a file for the final
    positions and velocities, sorted by atom id."""
    spacing = radius * (4.0 * math.pi / (3.0 * phi)) ** (1.0 / 3.0)
    mass = 4.0 / 3.0 * math.pi * radius ** 3 * density
    # LAMMPS's SI temperature: (3/2) k_B T = (1/2) m <v^2>, with <v^2> = speed^2.
    temperature = mass * speed ** 2 / (3.0 * 1.380649e-23)
    plugin = f"plugin load {PLUGIN}" if pair_style.startswith("bounce") else ""
    write = f"write_dump all custom {dump} id x y z vx vy vz modify sort id format float %.17g" if dump else ""
    return f"""
units si
atom_style sphere
boundary p p p
comm_modify vel yes
lattice sc {spacing!r}
region box block 0 {cells} 0 {cells} 0 {cells}
create_box 1 box
create_atoms 1 box
set type 1 diameter {2 * radius!r}
set type 1 mass {mass!r}
velocity all create {temperature!r} {seed} dist gaussian mom yes rot no loop geom
{plugin}
pair_style {pair_style}
pair_coeff * * {coeff}
neighbor {(0.2 * radius if skin is None else skin)!r} bin
neigh_modify delay 0 every 1 check yes
timestep {dt!r}
fix 1 all nve/sphere
compute ke all ke
thermo_style custom step c_ke
thermo_modify format float %.17g
thermo {thermo}
{extra}
run {steps}
{write}
"""


def restart_and_continue(first, steps, cores, work):
    """`first` (a script that sets up and runs), then `write_restart, run steps` in the same process,
    and `read_restart, run steps` in a second one given only the plugin, neighbor settings and the
    integrator: the two final states ({id: (x, y, z, vx, vy, vz)}) and the two processes' logs."""
    dump = "write_dump all custom {} id x y z vx vy vz modify sort id format float %.17g"
    log = run_in(work, first + f"\nwrite_restart gas.restart\nrun {steps}\n{dump.format('one.dump')}\n", cores,
                 "in.first")
    second = f"""
plugin load {PLUGIN}
read_restart gas.restart
neighbor 2e-4 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
run {steps}
{dump.format('two.dump')}
"""
    log2 = run_in(work, second, cores, "in.second")
    return read_dump(os.path.join(work, "one.dump")), read_dump(os.path.join(work, "two.dump")), log, log2


def thermo_rows(output):
    """(step, value, ...) rows of the thermo table(s) LAMMPS printed."""
    rows, reading = [], False
    for line in output.splitlines():
        if line.split()[:1] == ["Step"]:  # (LAMMPS 20250204 right-aligns it: "   Step")
            reading = True
            continue
        if reading:
            if line.startswith("WARNING"):  # LAMMPS's warnings can come inside the table
                continue
            parts = line.split()
            try:
                rows.append(tuple(float(p) for p in parts))
            except ValueError:
                reading = False
    return rows


def read_dump(path):
    """{id: (x, y, z, vx, vy, vz)} of a write_dump custom file."""
    atoms, lines = {}, open(path).read().splitlines()
    start = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS"))) + 1
    for line in lines[start:]:
        values = line.split()
        atoms[int(values[0])] = tuple(float(v) for v in values[1:])
    return atoms


def wall_collision(pair, model, velocity, steps_per_contact=1000, tangential_velocity=0.0, wall_args=None):
    """One sphere hitting a flat wall (fix wall/bounce zplane 0 NULL) as `bounce collide --wall`
    (or `--rigid-wall` with rigid_wall in `pair`): it touches the wall at t = 0 moving at -velocity
    along z (and `tangential_velocity` along x). Returns (eps^N, eps^T, bounce's record)."""
    options = dict(pair, **model)
    extra = ["--tangential-velocity", str(tangential_velocity)] if tangential_velocity else []
    cli = cli_args({k: v for k, v in options.items() if k != "rigid_wall"})
    cli += ["--rigid-wall"] if pair.get("rigid_wall") == "yes" else ["--wall"]
    ref = bounce(*cli, "--velocity", str(velocity), *extra)
    body = ref["pair"]["body1"]
    r, m = body["radius"], body["mass"]
    dt = ref["contact_time"] / steps_per_contact
    steps = int(3 * steps_per_contact)
    keys = {k: v for k, v in options.items() if not k.startswith("radius") and k != "model"}
    if wall_args is None:
        wall_args = f"zplane 0 NULL {model['model']} " + coeff_args(keys)
    box = 6 * r
    script = preamble(box, 1) + f"""
create_atoms 1 single 0 0 {r!r}
set atom 1 diameter {2 * r!r} mass {m!r}
velocity all set {tangential_velocity!r} 0 {-velocity!r}
plugin load {PLUGIN}
pair_style bounce
pair_coeff * * hertz E 1e9 nu 0.3
fix 1 all nve/sphere
fix 2 all wall/bounce {wall_args}
compute spin all property/atom omegay
compute w all reduce sum c_spin
variable w equal c_w
thermo_style custom step v_w
thermo {steps}
timestep {dt!r}
run {steps}
print "STATE $(vx[1]:%.17g) $(vz[1]:%.17g) $(v_w:%.17g)"
"""
    _, output = run_lammps(script)
    vx, vz, wy = map(float, re.findall(r"^STATE (.*)$", output, re.M)[-1].split())
    eps_n = vz / velocity
    # Contact point velocity along x: vx + (omega x (-R z))_x = vx - R omega_y.
    eps_t = (vx - r * wy) / tangential_velocity if tangential_velocity else float("nan")
    return eps_n, eps_t, ref


def krijt_collision(pair, model, velocity, steps_per_hertz_time=100, span=8.0, integration="corrected", extra=""):
    """A head-on collision of two spheres touching at t = 0 in LAMMPS with pair_style bounce's
    krijt, dt = t_H / steps_per_hertz_time with K13's Hertz time (22) at this speed, run for
    `span` t_H (`extra`: script lines before the run). Returns a dict: cor (0 where the grains
    stick: their contact still holds, pe != 0, or they approach again), closure (ke + pe + crack- and bulk-dissipated
    energy at the end, less the impact energy, over it: compute pair bounce), stuck, and
    bounce's record `ref`. (Other models have no pe: for them only cor is meaningful.)"""
    ref = bounce(*cli_args(dict(pair, **model)), "--velocity", str(velocity))
    t_hertz = ref["closed_forms"]["hertz_time_k13_22"] if "closed_forms" in ref else ref["contact_time"]
    b1, b2 = ref["pair"]["body1"], ref["pair"]["body2"]
    r1, r2, m1, m2 = b1["radius"], b2["radius"], b1["mass"], b2["mass"]
    dt = t_hertz / steps_per_hertz_time
    steps = int(span * steps_per_hertz_time)
    v1, v2 = velocity * m2 / (m1 + m2), -velocity * m1 / (m1 + m2)
    materials = {k: v for k, v in pair.items() if not k.startswith("radius")}
    script = preamble(4 * (r1 + r2), 2) + f"""
create_atoms 1 single {-r1} 0 0
create_atoms 2 single {r2} 0 0
set atom 1 diameter {2 * r1} mass {m1}
set atom 2 diameter {2 * r2} mass {m2}
velocity all set 0 0 0
set atom 1 vx {v1!r}
set atom 2 vx {v2!r}
plugin load {PLUGIN}
pair_style bounce integration {integration}
{pair_coeffs(materials, model)}
neighbor {max(r1, r2) * 0.6} bin
timestep {dt!r}
fix 1 all nve/sphere
compute e all pair bounce
variable total equal ke+pe+c_e[1]+c_e[2]
thermo_style custom step ke pe c_e[1] c_e[2] v_total
thermo {steps}
{extra}
run {steps}
print "STATE $(vx[1]:%.17g) $(vx[2]:%.17g) $(pe:%.17g) $(v_total:%.17g)"
"""
    _, output = run_lammps(script)
    vx1, vx2, pe, total = final_state(output)
    energy = 0.5 * m1 * m2 / (m1 + m2) * velocity ** 2
    # Stuck: the contact holds, or the neck broke while it pulled the grains back together, so
    # that they meet again (as bounce collide has it, K13's sticking).
    stuck = pe != 0.0 or vx2 - vx1 <= 0.0
    return dict(cor=0.0 if stuck else (vx2 - vx1) / velocity, closure=(total - energy) / energy, stuck=stuck,
                ref=ref, output=output)
