"""rbdbench: the shared machinery of rbdPacking's benchmarks.

A benchmark script (benchmarks/<name>) lists its cases, runs the missing
ones and writes docs/<name>.md with its tables and plots:

    import rbdbench as rb
    args = rb.parser('what it measures').parse_args()
    bench = rb.Benchmark('sphereSpeed', args)
    cases = [rb.Case('n500', rb.sphereBed(number=500, tubeDiameter=0.1),
                     params={'n': 500})]
    results = bench.run(cases)            # list of dicts, one per case
    report = bench.report('Title', 'One paragraph on what it measures.')
    report.table(['n', 'time [s]'], [[r['n'], r['wallTime']] ...])
    report.figure(fig, 'scaling', 'caption')
    report.write()

Cases
    A case is a packingDict, made from a nested Python dict (sphereBed()
    gives the paper's Table 3 sphere bed) with overrides 'block/entry':
    value (None removes an entry), written in full into
    benchmarks/run/<benchmark>/<case>-<hash>/system/packingDict, so every
    run directory states its own settings. The hash is that of the
    dictionary text (and of the command): a changed setting is a new run.

Cache
    benchmarks/run/<benchmark>/results.csv holds one row per (case, hash):
    the case's parameters, the summary of rbdPackBed flattened
    ('bulkPorosityCorrelations/dixon', ...), process wall time, CPU time,
    peak memory, exit status, the git commit and the date. A rerun runs
    only the cases without a row (or, with --force, all; with --rerun
    REGEX, the matching ones; with --stale, those run at another commit).
    The run directories keep the log, the summary, the profiles and
    constant/triSurface/pellets.stl; the other STL and the CFD case files
    are deleted after the run (--keep-files keeps them).

Resume
    A case without a row, or whose row says timeout (with --retry), whose
    run directory holds an rbdPackBed checkpoint
    (postProcessing/rbdPackBed/checkpoint: the run was stopped, by a
    timeout or a killed session) is continued with rbdPackBed -resume, not
    started again (--force, --rerun and --stale start anew); its earlier logs are kept as log.1, log.2, ... The
    summary's wallTime then is the packing time of all the runs together
    (up to the checkpoint each resumed from); the process wall time, CPU
    time and memory columns are those of the last run only, and the
    'resumes' column says how many runs came before it.

Environment
    rbdPackBed is taken from this repository's etc/bashrc (sourced once),
    unless the environment already has RBD_PACKING_DIR pointing here.

Common options: -j N, --quick, --dry-run, --force, --rerun REGEX,
--stale, --report-only, --timeout S, --set block/entry=value, --list,
--out DIR. The report states the command that reproduces it.
"""

import argparse
import copy
import csv
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shlex
import shutil
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BENCHMARKS = ROOT / 'benchmarks'
RUN = BENCHMARKS / 'run'
DOCS = ROOT / 'docs'


# ---------------------------------------------------------------------------
# packingDict: the paper's Table 3 beds, overrides, writing

#: Paper, Table 3: pellet density [kg/m^3], pellet-pellet friction and
#: restitution, pellet-wall friction and restitution; bed altitude 120 mm,
#: bulk porosity up to 100 mm
TABLE3 = {
    'density': 8030,
    'pelletFriction': 0.1,
    'pelletRestitution': 0.9,
    'wallFriction': 0.6,
    'wallRestitution': 0.6,
    'bedHeight': 0.12,
    'porosityHeight': 0.1,
}


def loadingEndTime(number, dp=0.01, spacing=1.2, columns=1, g=9.81):
    """endTime [s] for a bed of 'number' pellets whose loading would not
    fit in 30 s (the fixed default of engines before aba4643), else None:
    the entry is left out, so the beds run before keep their dictionaries
    and cached runs. A column releases its next pellet when the previous
    one has fallen 'spacing' dp: every sqrt(2 spacing dp/g) s (0.049 s for
    10 mm spheres); more than 25 s of loading gets twice that plus 10 s
    for settling. rbdPackBed now fits endTime to the loading itself when
    it is not given (packedBed::endTimeForLoading, twice the loading + 10
    s beyond 30 s); this keeps the benchmarks the same on older engines."""
    loading = number / columns * math.sqrt(2 * spacing * dp / g)
    if loading <= 25:
        return None
    return round(2 * loading + 10)


def fitEndTimeToLoading(d, number, dp=0.01):
    """Set simulation/endTime of the bed dictionary d to
    loadingEndTime(number) where that is not None."""
    endTime = loadingEndTime(number, dp=dp)
    if endTime:
        d['simulation']['endTime'] = endTime
    return d


def sphereBed(tubeDiameter, dp=0.01, fillHeight=None, number=None,
              tubeHeight=None, seed=1, positionDisturbance=0.1,
              porosityHeight=None, sleepVelocity=0.001):
    """The paper's Table 3 sphere bed as a packingDict (nested dict).

    tubeDiameter, dp, fillHeight, tubeHeight, porosityHeight [m]; give
    fillHeight or number. tubeHeight defaults to the fill height (or a
    conservative height for 'number' spheres at porosity 0.5) plus 3 dp.
    positionDisturbance [dp]: release offsets, so that seeds differ (the
    paper's 'slightly perturbed initial pellet positions').
    sleepVelocity [m/s]: as in tutorials/spheres (0: off).
    """
    if (fillHeight is None) == (number is None):
        raise ValueError('give exactly one of fillHeight and number')
    if tubeHeight is None:
        if fillHeight is not None:
            filled = fillHeight
        else:
            filled = (number * math.pi * dp**3 / 6
                      / (0.5 * math.pi * tubeDiameter**2 / 4))
        tubeHeight = round(filled + 3 * dp, 6)
    pellets = {
        'shape': 'sphere',
        'diameter': dp,
        'faces': 20,
        'density': TABLE3['density'],
        'friction': TABLE3['pelletFriction'],
        'restitution': TABLE3['pelletRestitution'],
        'rotation': True,
    }
    if fillHeight is not None:
        pellets['fillHeight'] = fillHeight
    else:
        pellets['number'] = number
    analysis = {'radialBins': 100, 'axialBins': 100}
    if porosityHeight is not None:
        analysis['porosityHeight'] = porosityHeight
    return {
        'container': {
            'type': 'cylinder',
            'diameter': tubeDiameter,
            'height': tubeHeight,
            'friction': TABLE3['wallFriction'],
            'restitution': TABLE3['wallRestitution'],
        },
        'pellets': pellets,
        'loading': {
            'scheme': 'column',
            'tilt': 45,
            'positionDisturbance': positionDisturbance,
            'angleDisturbance': 0,
            'seed': seed,
        },
        'simulation': {
            'sleepVelocity': sleepVelocity,
        },
        'analysis': analysis,
        # Only the packing is measured: small binary STL, deleted after
        'cfdCase': {'stlFormat': 'binary', 'overwrite': True},
    }


def pelletBed(shape, tubeDiameter, seed=1, fillHeight=None, number=None,
              **kwargs):
    """The Table 3 bed of the paper's pellets: 'sphere' (dp 10 mm),
    'cylinder' (d = h = 10 mm) or 'ring' (10/6/10 mm: outer diameter,
    inner diameter, height). Other keywords as sphereBed()."""
    d = sphereBed(tubeDiameter, dp=0.01, seed=seed, fillHeight=fillHeight,
                  number=number, **kwargs)
    p = d['pellets']
    if shape == 'sphere':
        return d
    p['shape'] = shape
    del p['faces']          # the default meshes are Table 3's: 4400, 8008
    p['height'] = 0.01
    if shape == 'ring':
        p['innerDiameter'] = 0.006
    elif shape != 'cylinder':
        raise ValueError('unknown shape ' + shape)
    return d


def readBinaryStlVertices(path):
    """The vertices (n x 3, float) of the triangles of a binary STL file,
    or None if the file is not binary STL."""
    import numpy as np
    raw = Path(path).read_bytes()
    if len(raw) < 84:
        return None
    n = int(np.frombuffer(raw[80:84], dtype='<u4')[0])
    if len(raw) != 84 + 50 * n:
        return None
    rec = np.dtype([('normal', '<f4', 3), ('v', '<f4', (3, 3)),
                    ('attr', '<u2')])
    tris = np.frombuffer(raw[84:], dtype=rec, count=n)
    return tris['v'].reshape(-1, 3).astype(float)


def volumeTrueMove(caseDir):
    """The largest vertex move [m] of the volume-true facets of
    pellets.stl, as caseDir's log prints it; 0 where it prints none (an
    older run, or an stl pellet written as given)."""
    log = Path(caseDir) / 'log'
    if not log.exists():
        return 0.0
    m = re.search(r'vertices moved by at most (\S+) m',
                  log.read_text(errors='replace'))
    return float(m.group(1)) if m else 0.0


def protrusion(caseDir, D, H, tubeDiameter, tubeHeight, samples=720):
    """Per pellet of caseDir's pellets.csv, the largest distance [m] by
    which it crosses the tube wall, the floor or the tube's top (negative:
    inside; inf for a NaN pose), as a numpy array. None without
    pellets.csv.

    Measured on the pellet meshes the packing simulated (constant/
    triSurface/pellets.stl, binary; each vertex assigned to the pellet
    whose centre is nearest): the exact tube contacts of cylinders and
    rings hold the vertices of the meshes' rim polygons, and the circle
    through them crosses the wall by up to the sagitta of a rim segment.
    pellets.stl holds the volume-true facets (pelletMeshes
    facets::volumeTrue): each boundary loop of a cylinder or a ring (the
    shapes this is asked for) offset radially to the area of its circle,
    by (maxMove/(D/2)) times its radius, maxMove
    the largest vertex move the log prints. Those facets stand out of the
    mesh that packed by up to maxMove (0.65 % of d for a 200-face
    cylinder), so the vertices are moved back, radially about the body
    axis by the factor 1/(1 + maxMove/(D/2)), before they are measured:
    the protrusion is that of the pellets as they packed. Without a
    binary pellets.stl: the exact outer cylinder (diameter D, height H,
    axis the body z axis; rims sampled at `samples` points)."""
    import numpy as np
    path = Path(caseDir) / 'postProcessing' / 'rbdPackBed' / 'pellets.csv'
    if not path.exists():
        return None
    data = np.genfromtxt(path, delimiter=',', names=True, dtype=None,
                         encoding=None)
    data = np.atleast_1d(data)
    if data.size == 0:
        return np.zeros(0)
    c = np.stack([data['x'], data['y'], data['z']], axis=1).astype(float)
    q = np.stack([data['qw'], data['qx'], data['qy'], data['qz']],
                 axis=1).astype(float)
    bad = ~np.all(np.isfinite(np.hstack([c, q])), axis=1)

    def beyond(pts):
        radial = np.sqrt(pts[..., 0]**2 + pts[..., 1]**2) - tubeDiameter / 2
        return np.maximum(np.maximum(radial, -pts[..., 2]),
                          pts[..., 2] - tubeHeight)

    if not bad.all():
        q[~bad] /= np.linalg.norm(q[~bad], axis=1, keepdims=True)
    w, x, y, z = q.T
    # body axes in the world: columns of the rotation matrix
    u = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z),
                  2 * (x * z - w * y)], axis=1)
    v = np.stack([2 * (x * y - w * z), 1 - 2 * (x * x + z * z),
                  2 * (y * z + w * x)], axis=1)
    a = np.stack([2 * (x * z + w * y), 2 * (y * z - w * x),
                  1 - 2 * (x * x + y * y)], axis=1)

    stl = Path(caseDir) / 'constant' / 'triSurface' / 'pellets.stl'
    verts = readBinaryStlVertices(stl) if stl.exists() else None
    if verts is not None and not bad.any():
        # The volume-true offset of the written facets, taken back
        moved = volumeTrueMove(caseDir)
        back = (moved / (D / 2)) / (1 + moved / (D / 2)) if moved else 0
        worst = np.full(len(c), -np.inf)
        for start in range(0, len(verts), 20000):
            chunk = verts[start:start + 20000]
            owner = np.argmin(((chunk[:, None, :] - c[None, :, :])**2)
                              .sum(axis=2), axis=1)
            if back:
                d = chunk - c[owner]
                ax = a[owner]
                radial = d - (d * ax).sum(axis=1)[:, None] * ax
                chunk = chunk - back * radial
            np.maximum.at(worst, owner, beyond(chunk))
        return worst
    theta = np.linspace(0, 2 * np.pi, samples, endpoint=False)
    rim = (np.cos(theta)[None, :, None] * u[:, None, :]
           + np.sin(theta)[None, :, None] * v[:, None, :]) * (D / 2)
    pts = np.concatenate([c[:, None, :] + s * (H / 2) * a[:, None, :] + rim
                          for s in (-1, 1)], axis=1)
    worst = beyond(pts).max(axis=1)
    worst[bad] = np.inf
    return worst


def applyOverrides(d, overrides):
    """A copy of the nested dict d with overrides {'a/b': value} applied;
    value None removes the entry."""
    d = copy.deepcopy(d)
    for path, value in (overrides or {}).items():
        keys = path.split('/')
        node = d
        for k in keys[:-1]:
            node = node.setdefault(k, {})
        if value is None:
            node.pop(keys[-1], None)
        else:
            node[keys[-1]] = value
    return d


def foamValue(v):
    """A Python value as OpenFOAM dictionary text."""
    if isinstance(v, bool):
        return 'true' if v else 'false'
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return '(' + ' '.join(foamValue(x) for x in v) + ')'
    s = str(v)
    if re.fullmatch(r'[A-Za-z0-9_.:+\-]+', s):
        return s
    return '"' + s.replace('"', '\\"') + '"'


def foamDictText(d, indent=0):
    """A nested dict as the body of an OpenFOAM dictionary."""
    pad = ' ' * indent
    lines = []
    for key, value in d.items():
        if isinstance(value, dict):
            lines.append(pad + key)
            lines.append(pad + '{')
            lines.append(foamDictText(value, indent + 4))
            lines.append(pad + '}')
        else:
            lines.append('%s%-20s %s;' % (pad, key, foamValue(value)))
    return '\n'.join(line for line in lines if line != '')


def packingDictText(d, origin=''):
    head = (
        '/*--------------------------------*- C++ -*------------------------'
        '----------*\\\n'
        '  rbdPacking benchmark case%s\n'
        '\\*----------------------------------------------------------------'
        '-----------*/\n'
        'FoamFile\n{\n    version     2.0;\n    format      ascii;\n'
        '    class       dictionary;\n    location    "system";\n'
        '    object      packingDict;\n}\n\n'
    ) % ((': ' + origin) if origin else '')
    return head + foamDictText(d) + '\n'


def parseSetOption(items):
    """--set block/entry=value strings as an overrides dict (values parsed
    as numbers or booleans where they look like them)."""
    out = {}
    for item in items or []:
        if '=' not in item:
            raise SystemExit("--set needs block/entry=value, not '%s'"
                             % item)
        k, v = item.split('=', 1)
        if v.strip().startswith('{'):
            raise SystemExit("--set takes one entry, not a dictionary "
                             "('%s'): give each as block/sub/entry=value"
                             % item)
        out[k.strip()] = parseScalar(v.strip())
    return out


# ---------------------------------------------------------------------------
# Reading rbdPackBed's outputs

def parseScalar(s):
    low = s.lower()
    if low in ('true', 'yes', 'on'):
        return True
    if low in ('false', 'no', 'off'):
        return False
    try:
        return int(s)
    except ValueError:
        pass
    try:
        return float(s)
    except ValueError:
        return s


def parseFoamDict(text):
    """An OpenFOAM dictionary (as rbdPackBed's summary) as a nested dict;
    the FoamFile header is dropped, lists are kept as lists of tokens."""
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    text = re.sub(r'//[^\n]*', ' ', text)
    tokens = re.findall(r'"[^"]*"|[{};()]|[^\s{};()]+', text)
    pos = 0

    def block():
        nonlocal pos
        d = {}
        while pos < len(tokens):
            t = tokens[pos]
            if t == '}':
                pos += 1
                return d
            key = t.strip('"')
            pos += 1
            if pos < len(tokens) and tokens[pos] == '{':
                pos += 1
                d[key] = block()
                continue
            values = []
            depth = 0
            while pos < len(tokens) and not (tokens[pos] == ';'
                                             and depth == 0):
                if tokens[pos] == '(':
                    depth += 1
                elif tokens[pos] == ')':
                    depth -= 1
                values.append(tokens[pos])
                pos += 1
            pos += 1   # ';'
            if len(values) == 1:
                d[key] = parseScalar(values[0].strip('"'))
            else:
                d[key] = [parseScalar(v) for v in values
                          if v not in '()']
        return d

    d = block()
    d.pop('FoamFile', None)
    return d


def flatten(d, prefix=''):
    out = {}
    for k, v in d.items():
        key = prefix + k
        if isinstance(v, dict):
            out.update(flatten(v, key + '/'))
        else:
            out[key] = v
    return out


def readSummary(caseDir):
    p = Path(caseDir) / 'postProcessing' / 'rbdPackBed' / 'summary'
    return parseFoamDict(p.read_text())


#: The closing statistics line of rbdPackBed's log
_LOG_STATS = re.compile(
    r'Simulated (?P<t>\S+) s in (?P<steps>\d+) steps \(smallest '
    r'(?P<minStep>\S+) s\), (?P<collisions>\d+) collisions'
    r'(?: \((?P<impulses>\d+) impulses in (?P<sweeps>\d+) sweeps\))?, '
    r'(?P<restingSolves>\d+) resting-contact solves \((?P<lcpIterations>\d+)'
    r' LCP iterations, largest island (?P<largestIsland>\d+) contacts, '
    r'(?P<lcpFailures>\d+) not converged\), (?P<projections>\d+) overlap '
    r'corrections')


#: A progress line of rbdPackBed's log
_LOG_PROGRESS = re.compile(
    r'^Time = (?P<time>\S+) s  pellets (?P<released>\d+)/(?P<number>\d+)'
    r'.*  steps (?P<steps>\d+).*ExecutionTime = (?P<exec>\S+) s', re.M)


def readLogStatistics(log):
    """What rbdPackBed's log says beyond the summary:
        log/restingSolves, log/lcpIterations, log/largestIsland,
        log/projections, log/minStep    (its closing statistics line)
        log/time [s], log/released, log/steps, log/executionTime [s]
                                        (how far a run got that timed out:
                                        its closing statistics line and
                                        wall time where a stopped run wrote
                                        them, else its last progress line)
    Entries the log does not have are left out."""
    try:
        text = Path(log).read_text(errors='replace')
    except OSError:
        return {}
    out = {}
    m = None
    for m in _LOG_STATS.finditer(text):
        pass
    if m is not None:
        out.update({'log/' + k: parseScalar(m.group(k))
                    for k in ('restingSolves', 'lcpIterations',
                              'largestIsland', 'projections', 'minStep')})
    m = None
    for m in _LOG_PROGRESS.finditer(text):
        pass
    if m is not None:
        out.update({'log/time': parseScalar(m.group('time')),
                    'log/released': parseScalar(m.group('released')),
                    'log/steps': parseScalar(m.group('steps')),
                    'log/executionTime': parseScalar(m.group('exec'))})
    # A run stopped by a signal closes with its statistics at the time it
    # stopped, after the last progress line
    m = None
    for m in _LOG_STATS.finditer(text):
        pass
    if m is not None:
        out['log/time'] = parseScalar(m.group('t'))
        out['log/steps'] = parseScalar(m.group('steps'))
        w = None
        for w in re.finditer(r'^Wall time (\S+) s', text, re.M):
            pass
        if w is not None:
            out['log/executionTime'] = parseScalar(w.group(1))
    return out


def readDat(path):
    """Columns of a '#'-commented .dat file as a 2D numpy array."""
    import numpy as np
    return np.loadtxt(path, comments='#', ndmin=2)


# ---------------------------------------------------------------------------
# Environment and machine

_env = None


def environment():
    """The environment with this repository's rbdPackBed on PATH."""
    global _env
    if _env is not None:
        return _env
    here = os.environ.get('RBD_PACKING_DIR')
    if (here and Path(here).resolve() == ROOT
            and shutil.which('rbdPackBed')):
        _env = dict(os.environ)
        return _env
    out = subprocess.run(
        ['bash', '-c', '. "%s/etc/bashrc" >/dev/null 2>&1; env -0' % ROOT],
        capture_output=True, check=True).stdout.decode()
    _env = dict(item.split('=', 1) for item in out.split('\0') if '=' in item)
    return _env


def repoPath(p):
    """p relative to the repository root if it lies inside it, else
    absolute (as a string)."""
    p = Path(p).resolve()
    try:
        return str(p.relative_to(ROOT))
    except ValueError:
        return str(p)


def _run(cmd, **kw):
    try:
        return subprocess.run(cmd, capture_output=True, text=True,
                              **kw).stdout.strip()
    except OSError:
        return ''


def gitCommit():
    commit = _run(['git', '-C', str(ROOT), 'rev-parse', '--short=10',
                   'HEAD'])
    dirty = _run(['git', '-C', str(ROOT), 'status', '--porcelain',
                  '--untracked-files=no', '--', 'src', 'applications'])
    return commit + ('+local changes' if dirty else '')


def machineInfo():
    info = {}
    try:
        cpuinfo = Path('/proc/cpuinfo').read_text()
        m = re.search(r'model name\s*:\s*(.*)', cpuinfo)
        info['CPU'] = m.group(1).strip() if m else platform.processor()
    except OSError:
        info['CPU'] = platform.processor()
    info['cores (os.cpu_count)'] = os.cpu_count()
    try:
        mem = Path('/proc/meminfo').read_text()
        kb = int(re.search(r'MemTotal:\s*(\d+)', mem).group(1))
        info['memory'] = '%.1f GiB' % (kb / 2**20)
    except (OSError, AttributeError):
        pass
    try:
        osr = Path('/etc/os-release').read_text()
        info['OS'] = re.search(r'PRETTY_NAME="?([^"\n]*)', osr).group(1)
    except (OSError, AttributeError):
        info['OS'] = platform.platform()
    info['kernel'] = platform.release()
    env = environment()
    info['OpenFOAM'] = env.get('WM_PROJECT_VERSION', '?')
    info['compiler'] = _run(['g++', '--version']).split('\n')[0]
    info['rbdPackBed'] = shutil.which('rbdPackBed', path=env.get('PATH'))
    info['git commit'] = gitCommit()
    info['load average (1, 5, 15 min) at start'] = ' '.join(
        '%.2f' % x for x in os.getloadavg())
    return info


# ---------------------------------------------------------------------------
# Cases and runs

class Case:
    """One run: a name, a packingDict (nested dict, or the path of a file
    copied verbatim), parameters for the tables, and optionally another
    command (default: rbdPackBed -case .)."""

    def __init__(self, name, packingDict=None, params=None, command=None,
                 dictFile=None, copyDir=None, prepare=None):
        self.name = name
        self.packingDict = packingDict
        self.dictFile = Path(dictFile) if dictFile else None
        self.copyDir = Path(copyDir) if copyDir else None
        self.prepare = prepare
        self.params = dict(params or {})
        self.command = command or ['rbdPackBed', '-case', '.']

    def dictText(self, overrides=None):
        if self.packingDict is not None:
            return packingDictText(applyOverrides(self.packingDict,
                                                  overrides), self.name)
        if self.dictFile is not None:
            return self.dictFile.read_text()
        return ''

    def hash(self, overrides=None):
        h = hashlib.sha1()
        h.update(self.dictText(overrides).encode())
        h.update(json.dumps(self.command).encode())
        if self.copyDir is not None:
            for p in sorted(self.copyDir.rglob('*')):
                if p.is_file():
                    h.update(str(p.relative_to(self.copyDir)).encode())
                    h.update(p.read_bytes())
        if self.prepare is not None:
            h.update(json.dumps(self.prepare).encode())
        return h.hexdigest()[:8]


def runProcess(cmd, cwd, env, log, timeout=None, watch=None):
    """Run cmd in cwd with its output in the file log; returns a dict with
    exitCode, status ('ok', 'failed', 'timeout'), processWallTime [s],
    cpuTime [s] (user + sys of the process and its children), maxRSS [MiB]
    and, with watch (a directory), logStart: first-seen times [s from the
    start] of the files log.* appearing in it (polled every 0.25 s)."""
    start = time.monotonic()
    with open(log, 'w') as out:
        p = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=out,
                             stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL,
                             start_new_session=True)
    seen = {}
    status = None
    timedOut = False
    while True:
        pid, st, ru = os.wait4(p.pid, os.WNOHANG)
        if pid == p.pid:
            status, rusage = st, ru
            break
        now = time.monotonic() - start
        if watch is not None:
            for f in Path(watch).glob('log.*'):
                seen.setdefault(f.name, now)
        if timeout and now > timeout and not timedOut:
            timedOut = True
            try:
                os.killpg(p.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        time.sleep(0.25)
    p.returncode = os.waitstatus_to_exitcode(status)
    wall = time.monotonic() - start
    # wait4 of the direct child: its own usage and that of its waited-for
    # children (the OpenFOAM applications of an Allrun)
    result = {
        'exitCode': p.returncode,
        'status': ('timeout' if timedOut else
                   'ok' if p.returncode == 0 else 'failed'),
        'processWallTime': round(wall, 3),
        'cpuTime': round(rusage.ru_utime + rusage.ru_stime, 3),
        'maxRSS': round(rusage.ru_maxrss / 1024, 1),
    }
    if watch is not None:
        result['logStart'] = seen
    return result


#: Cache columns kept as text: a commit or hash of digits and one 'e'
#: ('073842e235') would otherwise read as a number
_TEXT_COLUMNS = {'case', 'hash', 'status', 'commit', 'date', 'dir'}


class Benchmark:
    """Runs a benchmark's cases with a CSV cache and writes its report."""

    def __init__(self, name, args):
        self.name = name
        self.args = args
        self.quick = bool(getattr(args, 'quick', False))
        tag = name + ('-quick' if self.quick else '')
        self.runDir = Path(args.runDir) / tag if args.runDir else RUN / tag
        self.csvPath = self.runDir / 'results.csv'
        if args.out:
            self.outDir = Path(args.out)
        else:
            self.outDir = self.runDir if self.quick else DOCS
        self.overrides = parseSetOption(args.set)
        self.lock = threading.Lock()
        self.rows = self._readCsv()
        # Cases asked for with no result for their settings (run())
        self.notRun = []
        self.started = datetime.datetime.now()
        self.machine = None

    # cache

    def _readCsv(self):
        rows = {}
        if self.csvPath.exists():
            with open(self.csvPath, newline='') as f:
                for row in csv.DictReader(f):
                    rows[(row['case'], row['hash'])] = {
                        k: (None if v == '' else v if k in _TEXT_COLUMNS
                            else parseScalar(v))
                        for k, v in row.items()}
        return rows

    def _writeCsv(self):
        keys = ['case', 'hash', 'status']
        for row in self.rows.values():
            for k in row:
                if k not in keys:
                    keys.append(k)
        self.runDir.mkdir(parents=True, exist_ok=True)
        tmp = self.csvPath.with_suffix('.csv.tmp')
        with open(tmp, 'w', newline='') as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            for key in sorted(self.rows):
                w.writerow({k: ('' if v is None else v)
                            for k, v in self.rows[key].items()})
        tmp.replace(self.csvPath)

    def caseDir(self, case):
        return self.runDir / ('%s-%s' % (case.name,
                                         case.hash(self.overrides)))

    def writeCase(self, case):
        d = self.caseDir(case)
        if d.exists():
            shutil.rmtree(d)
        if case.copyDir is not None:
            shutil.copytree(case.copyDir, d, symlinks=True)
        (d / 'system').mkdir(parents=True, exist_ok=True)
        text = case.dictText(self.overrides)
        if text:
            (d / 'system' / 'packingDict').write_text(text)
        if case.prepare:
            # foamDictionary edits of a copied case: [file, entry, value]
            for f, entry, value in case.prepare:
                subprocess.run(['foamDictionary', str(d / f), '-entry',
                                entry, '-set', str(value)],
                               env=environment(), check=True,
                               capture_output=True)
        return d

    def _needsRun(self, case):
        a = self.args
        key = (case.name, case.hash(self.overrides))
        row = self.rows.get(key)
        if a.force or row is None:
            return True
        if a.rerun and re.search(a.rerun, case.name):
            return True
        if a.stale and str(row.get('commit')) != gitCommit():
            return True
        if row.get('status') != 'ok' and a.retry:
            return True
        return False

    def _resumable(self, case):
        """The earlier logs of the case's stopped rbdPackBed run that left
        a checkpoint to resume from, or None."""
        d = self.caseDir(case)
        checkpoint = d / 'postProcessing' / 'rbdPackBed' / 'checkpoint'
        a = self.args
        row = self.rows.get((case.name, case.hash(self.overrides)))
        # Only a run that was stopped (no row: its session ended; or a
        # timeout) goes on; a finished one, even unsettled at endTime, and
        # a rerun asked for (--force, --rerun, --stale) start anew
        if (case.copyDir is not None or case.command[:1] != ['rbdPackBed']
                or not checkpoint.exists() or not (d / 'log').exists()
                or a.force or a.rerun or a.stale
                or (row is not None and row.get('status') != 'timeout')):
            return None
        return sorted(d.glob('log.[0-9]*'),
                      key=lambda f: int(f.suffix[1:]))

    def _runOne(self, case, index, total):
        h = case.hash(self.overrides)
        earlier = self._resumable(case)
        command = list(case.command)
        if earlier is None:
            d = self.writeCase(case)
            resumes = 0
        else:
            d = self.caseDir(case)
            resumes = len(earlier) + 1
            (d / 'log').rename(d / ('log.%d' % resumes))
            command.append('-resume')
        print('[%d/%d] %s: %s (in %s)' % (index, total, case.name,
                                          ' '.join(command),
                                          repoPath(d)),
              flush=True)
        watch = d if case.copyDir is not None else None
        res = runProcess(command, d, environment(), d / 'log',
                         timeout=self.args.timeout, watch=watch)
        row = {'case': case.name, 'hash': h, 'resumes': resumes}
        row.update(case.params)
        row.update(res)
        row.pop('logStart', None)
        summaryFile = d / 'postProcessing' / 'rbdPackBed' / 'summary'
        if summaryFile.exists():
            summary = flatten(readSummary(d))
            # The packing's own CPU time (all runs of a resumed case) is
            # not the process's (cpuTime above)
            if 'cpuTime' in summary:
                summary['packingCpuTime'] = summary.pop('cpuTime')
            # The run's status (settled, notSettled, ...) is not the
            # process's (status above: ok, failed, timeout)
            if 'status' in summary:
                summary['runStatus'] = summary.pop('status')
                # rbdPackBed exits 1 for a bed that did not settle (or
                # stacked, or is incomplete) after writing its report: the
                # process ran to its end, and the benchmarks judge the bed
                # by runStatus and settled
                if (row['status'] == 'failed' and row['exitCode'] == 1
                        and summary['runStatus'] != 'settled'):
                    row['status'] = 'ok'
            row.update(summary)
        row.update(readLogStatistics(d / 'log'))
        if watch is not None:
            row['logStart'] = json.dumps(res.get('logStart', {}))
        row['commit'] = gitCommit()
        row['date'] = datetime.datetime.now().isoformat(timespec='seconds')
        row['dir'] = str(repoPath(d))
        if not self.args.keepFiles and case.copyDir is None:
            # pellets.stl stays: the pellets as they packed, whose
            # vertices the protrusion check measures (protrusion)
            stl = d / 'constant' / 'triSurface' / 'pellets.stl'
            kept = stl.read_bytes() if stl.exists() else None
            for sub in ('constant', '0'):
                shutil.rmtree(d / sub, ignore_errors=True)
            if kept is not None:
                stl.parent.mkdir(parents=True)
                stl.write_bytes(kept)
            for f in (d / 'system').iterdir():
                if f.name != 'packingDict':
                    f.unlink()
        with self.lock:
            self.rows[(case.name, h)] = row
            self._writeCsv()
        print('[%d/%d] %s: %s, %.1f s%s' % (
            index, total, case.name, row['status'], row['processWallTime'],
            ('' if row['status'] == 'ok' else
             ' (see %s)' % repoPath(d / 'log'))), flush=True)
        return row

    def run(self, cases):
        """Run what is missing; returns the rows of the cases, in order
        (cases that never ran are left out)."""
        a = self.args
        names = [c.name for c in cases]
        if len(set(names)) != len(names):
            raise SystemExit('duplicate case names')
        if a.list:
            for c in cases:
                row = self.rows.get((c.name, c.hash(self.overrides)))
                state = (row['status'] + ', %.1f s' % row['processWallTime']
                         if row else 'not run')
                print('%-40s %s  %s' % (c.name, c.hash(self.overrides),
                                        state))
            raise SystemExit(0)
        if a.dryRun:
            for c in cases:
                d = self.writeCase(c)
                print('wrote %s: %s' % (repoPath(d),
                                        ' '.join(c.command)))
            print('dry run: %d cases written, nothing run' % len(cases))
            raise SystemExit(0)

        todo = [] if a.reportOnly else [c for c in cases
                                        if self._needsRun(c)]
        print('%s: %d cases, %d cached, %d to run with -j %d'
              % (self.name, len(cases), len(cases) - len(todo), len(todo),
                 a.jobs), flush=True)
        self.machine = machineInfo()
        if todo:
            with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
                futures = [ex.submit(self._runOne, c, i + 1, len(todo))
                           for i, c in enumerate(todo)]
                for f in futures:
                    f.result()
        out = []
        for c in cases:
            row = self.rows.get((c.name, c.hash(self.overrides)))
            if row is not None:
                row = dict(row)
                row.update(c.params)
                row['caseDir'] = ROOT / row['dir']
                out.append(row)
            else:
                # No result with these settings: the report says so (a
                # rerun with other options, say --engines or --end-time,
                # hashes its cases differently and would otherwise drop
                # the rows of the cached settings without a word)
                other = sorted(h for (n, h) in self.rows if n == c.name)
                self.notRun.append((c.name, c.hash(self.overrides), other))
        return out

    # report

    def command(self):
        """The command that reproduces the report: this one without the
        options that only steer the cache (--force, --report-only, ...)."""
        drop = {'--force', '--report-only', '--stale', '--retry', '--list',
                '--dry-run'}
        args = []
        skip = False
        for x in sys.argv[1:]:
            if skip:
                skip = False
            elif x in drop:
                pass
            elif x == '--rerun':
                skip = True
            elif not x.startswith('--rerun='):
                args.append(x)
        return ' '.join(['benchmarks/' + self.name]
                        + [shlex.quote(x) for x in args])

    def report(self, title, intro):
        return Report(self, title, intro)


# ---------------------------------------------------------------------------
# Reports

def fmt(v, spec='%.4g'):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return '-'
    if isinstance(v, str):
        return v
    if isinstance(v, bool):
        return 'yes' if v else 'no'
    if isinstance(v, int):
        return str(v)
    return spec % v


def mdTable(headers, rows):
    lines = ['| ' + ' | '.join(headers) + ' |',
             '|' + '|'.join('---' for _ in headers) + '|']
    for r in rows:
        lines.append('| ' + ' | '.join(str(x) for x in r) + ' |')
    return '\n'.join(lines)


def textTable(headers, rows):
    cols = list(zip(*([headers] + [[str(x) for x in r] for r in rows])))
    widths = [max(len(x) for x in c) for c in cols]
    line = lambda r: '  '.join(str(x).rjust(w) for x, w in zip(r, widths))
    return '\n'.join([line(headers), line(['-' * w for w in widths])]
                     + [line(r) for r in rows])


class Report:
    """docs/<name>.md: sections of text, tables and figures, the command,
    wall time per case and the machine."""

    def __init__(self, bench, title, intro):
        self.bench = bench
        self.title = title
        self.parts = [intro]
        self.figDir = bench.outDir / bench.name
        if bench.quick:
            self.parts.insert(0, '**Quick mode** (`--quick`): small beds '
                              'that check the benchmark runs, not its '
                              'results.')

    def text(self, s):
        self.parts.append(s)

    def section(self, title):
        self.parts.append('## ' + title)

    def table(self, headers, rows, caption=None):
        if caption:
            self.parts.append(caption)
        self.parts.append(mdTable(headers, rows))
        print()
        if caption:
            print(caption)
        print(textTable(headers, rows))

    def figure(self, fig, name, caption):
        import matplotlib
        self.figDir.mkdir(parents=True, exist_ok=True)
        path = self.figDir / (name + '.png')
        fig.savefig(path, dpi=110, bbox_inches='tight')
        matplotlib.pyplot.close(fig)
        rel = os.path.relpath(path, self.bench.outDir)
        self.parts.append('![%s](%s)\n\n*%s*' % (caption, rel, caption))
        print('plot: %s' % path)

    def wallTimes(self, rows, extra=None):
        """The wall time table of the runs (extra: [(header, key)])."""
        extra = extra or []
        headers = (['case', 'status', 'pellets', 'steps',
                    'simulated [s]', 'packing [s]', 'process [s]',
                    'CPU [s]', 'peak memory [MiB]']
                   + [h for h, _ in extra] + ['commit'])
        body = []
        stopped = False

        def sumOrLog(r, key, logKey, spec):
            # a run that did not finish has no summary: its log says how
            # far it got (readLogStatistics; marked *)
            nonlocal stopped
            if r.get(key) is not None or r.get(logKey) is None:
                return fmt(r.get(key), spec)
            stopped = True
            return fmt(r.get(logKey), spec) + ' *'

        resumed = False
        for r in rows:
            runs = int(r.get('resumes') or 0)
            resumed = resumed or runs > 0
            body.append([r['case'] + (' (%d runs) \u2020' % (runs + 1)
                                      if runs else ''),
                         r.get('status'),
                         fmt(r.get('pellets')),
                         sumOrLog(r, 'steps', 'log/steps', '%.4g'),
                         sumOrLog(r, 'simulatedTime', 'log/time', '%.3g'),
                         sumOrLog(r, 'wallTime', 'log/executionTime',
                                  '%.1f'),
                         fmt(r.get('processWallTime'), '%.1f'),
                         fmt(r.get('cpuTime'), '%.1f'),
                         fmt(r.get('maxRSS'), '%.0f')]
                        + [fmt(r.get(k)) for _, k in extra]
                        + [r.get('commit', '')])
        self.section('Wall time per case')
        self.text('`packing` is rbdPackBed\'s own timer (summary '
                  '`wallTime`: filling and settling); `process` is the '
                  'whole process (reading, packing, analysis, writing); '
                  'CPU is user + system time of the process.')
        self.parts.append(mdTable(headers, body))
        if resumed:
            self.text('\u2020 packed in several runs, each resumed from '
                      'the checkpoint of the one before (rbdPackBed '
                      '-resume, bit for bit the run that never stopped): '
                      '`packing` is the time of all of them up to the '
                      'last checkpoint (their CPU time: the summary\'s '
                      '`cpuTime`, column packingCpuTime of results.csv); '
                      '`process`, CPU and memory are those of the last '
                      'run.')
        if stopped:
            self.text('\\* a run that did not finish: simulated time, '
                      'steps and packing time where it stopped (the '
                      'closing statistics a stopped run writes, else its '
                      'last progress line).')

    def write(self):
        b = self.bench
        machine = b.machine or machineInfo()
        out = ['# ' + self.title, '']
        for p in self.parts:
            out += [p, '']
        if b.notRun:
            out += ['**Not in this report**: cases with no result for '
                    'these settings (run the command below without '
                    '`--report-only`; a result under other settings is '
                    'in the cache as the hash named):', '']
            out += ['- %s (settings %s)%s'
                    % (name, h, '; cached under ' + ', '.join(other)
                       if other else '')
                    for name, h, other in b.notRun]
            out += ['']
        out += ['## Reproduce', '',
                'From the repository root, after `./Allwmake` and '
                '`bin/tools/installDependencies -benchmarks`:', '',
                '```sh', b.command(), '```', '']
        if b.quick:
            out += ['These are quick numbers. The full benchmark is the '
                    'same command without `--quick` (and without '
                    '`--out`).', '']
        out += ['Cached results are reused (`%s`); `--force` reruns '
                'every case. Run directories: `%s/`.'
                % (repoPath(b.csvPath),
                   repoPath(b.runDir)), '',
                '## Machine', '']
        out += ['- %s: %s' % (k, v) for k, v in machine.items()]
        out += ['- report written: %s'
                % datetime.datetime.now().isoformat(timespec='seconds'), '']
        b.outDir.mkdir(parents=True, exist_ok=True)
        path = b.outDir / (b.name + '.md')
        path.write_text('\n'.join(out))
        print()
        print('report: %s' % path)
        print('rerun:  cd %s && %s' % (ROOT, b.command()))
        return path


# ---------------------------------------------------------------------------
# Command line

def parser(description, quickHelp='small beds that check the pipeline'):
    p = argparse.ArgumentParser(
        description=description,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('-j', '--jobs', type=int, default=1,
                   help='cases run in parallel (default 1)')
    p.add_argument('--quick', action='store_true',
                   help=quickHelp + '; report under benchmarks/run/'
                   '<name>-quick/ unless --out')
    p.add_argument('--dry-run', dest='dryRun', action='store_true',
                   help='write the case directories, run nothing')
    p.add_argument('--force', action='store_true',
                   help='rerun every case, cached or not')
    p.add_argument('--rerun', metavar='REGEX',
                   help='rerun the cases whose name matches')
    p.add_argument('--stale', action='store_true',
                   help='rerun the cases run at another git commit')
    p.add_argument('--retry', action='store_true',
                   help='rerun the cases that failed or timed out')
    p.add_argument('--report-only', dest='reportOnly', action='store_true',
                   help='run nothing, report the cached results')
    p.add_argument('--list', action='store_true',
                   help='list the cases and their cache state')
    p.add_argument('--timeout', type=float, default=None, metavar='S',
                   help='stop a case after S seconds (status timeout)')
    p.add_argument('--set', action='append', metavar='BLOCK/ENTRY=VALUE',
                   help='override a packingDict entry in every case '
                   '(repeatable; a new hash, so new runs)')
    p.add_argument('--keep-files', dest='keepFiles', action='store_true',
                   help='keep the STL and CFD case files of each run')
    p.add_argument('--out', metavar='DIR',
                   help='report directory (default docs/, quick: the run '
                   'directory)')
    p.add_argument('--run-dir', dest='runDir', metavar='DIR',
                   help='run directories and cache (default '
                   'benchmarks/run)')
    return p


def floats(s):
    return [float(x) for x in s.split(',') if x.strip()]


def ints(s):
    return [int(x) for x in s.split(',') if x.strip()]


def mean(xs):
    xs = [x for x in xs if x is not None and not
          (isinstance(x, float) and math.isnan(x))]
    return sum(xs) / len(xs) if xs else float('nan')


def std(xs):
    xs = [x for x in xs if x is not None]
    if len(xs) < 2:
        return float('nan')
    m = mean(xs)
    return math.sqrt(sum((x - m)**2 for x in xs) / (len(xs) - 1))


def num(r, key):
    """A result's entry as a float; NaN where it is missing or not a
    number."""
    v = r.get(key)
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return float(v)
    return float('nan')


#: Long runs write a checkpoint this often [s of wall time] and resume
#: from it when the same command is run again (Benchmark._resumable)
CHECKPOINT_INTERVAL = 600


def statusText(r):
    """A run's status; for a run that did not finish, how far it got (from
    its log)."""
    st = r.get('status')
    v = r.get('log/released')
    if st != 'ok' and v is not None:
        t, w = r.get('log/time'), r.get('log/executionTime')
        st += ' (%s pellets released, %s s simulated in %s s)' % (
            v, fmt(t, '%.2f'), fmt(w, '%.0f'))
    return st


def fitPower(xs, ys):
    """b and a of y = a x^b by least squares on the logarithms."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
           if x > 0 and y > 0 and not math.isnan(y)]
    if len(pts) < 2:
        return float('nan'), float('nan')
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx)**2 for p in pts)
    if sxx == 0:
        return float('nan'), float('nan')
    b = sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx
    return b, math.exp(my - b * mx)


def pyplot():
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    return plt
