#!/usr/bin/env python3
"""Writes the bad-input corpus (tests/bad-inputs/<kind>/<id>/...) and its manifest expected.tsv.

Every entry is one broken input plus what `cablefit` must answer: exit code, the file the error
line names, and a substring of the one-line message. Inputs that cannot live in git (a FIFO,
multi-gigabyte sparse files) are made by the test at run time from the `setup` column.
Run it from anywhere; it rewrites the corpus next to itself. Kept so the corpus can be extended
and regenerated, but the committed files are the corpus: the test reads those, not this script.
"""
import json
import os
import random
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
rows = []


def write(rel, data):
    p = os.path.join(HERE, rel)
    os.makedirs(os.path.dirname(p), exist_ok=True)
    with open(p, 'wb' if isinstance(data, bytes) else 'w') as f:
        f.write(data)


def entry(id_, command, exit_code, names, message, setup='-'):
    """command: cablefit arguments, paths relative to this folder, {out} = a fresh output dir."""
    rows.append((id_, setup, str(exit_code), names, message, command))


# ---------------------------------------------------------------- a valid case to break ----
CENTERLINE = 's,x,y,z\n' + ''.join(
    '%.4f,%.4f,0,%.5f\n' % (0.6 * i / 20, 0.45 * i / 20, -0.02 * (1 - (2 * i / 20 - 1) ** 2))
    for i in range(21))


def case(name='bad', length=0.6, cable=None, clamps=None, recordings=None, extra=None):
    c = {'format': 'cable-recording/1', 'name': name,
         'cable': cable if cable is not None else {
             'length': length, 'diameter': 0.006, 'bending_stiffness': 0.012,
             'torsional_stiffness': 0.009, 'linear_density': 0.05},
         'gravity': [0, 0, -9.81],
         'clamps': clamps if clamps is not None else [
             {'s': 0.0, 'position': [0, 0, 0], 'tangent': [1, 0, 0], 'normal': [0, 0, 1]},
             {'s': length, 'position': [0.45, 0, 0], 'tangent': [1, 0, 0],
              'normal': [0, 0, 1]}],
         'recordings': recordings if recordings is not None else [
             {'kind': 'centerline', 'file': 'centerline.csv'}]}
    if extra:
        c.update(extra)
    return json.dumps(c, indent=1)


def case_entry(id_, text, message, names='case.json', exit_code=2, command='diagnose',
               files=None):
    d = 'case/' + id_
    write(d + '/case.json', text)
    for name, data in (files if files is not None else {'centerline.csv': CENTERLINE}).items():
        write(d + '/' + name, data)
    entry(id_, command + ' ' + d + ' --out {out}', exit_code, d + '/' + names, message)


def with_cable(**kw):
    cable = {'length': 0.6, 'diameter': 0.006, 'bending_stiffness': 0.012,
             'torsional_stiffness': 0.009, 'linear_density': 0.05}
    cable.update(kw)
    return cable


# ---------------------------------------------------------------- case.json ---------------
good = case()
case_entry('case-truncated', good[:len(good) // 2], 'not valid JSON')
case_entry('case-empty', '', 'not valid JSON')
case_entry('case-not-object', '[1, 2, 3]', 'must be a JSON object')
case_entry('case-wrong-format', good.replace('cable-recording/1', 'cable-recording/9'),
           'cable-recording/9')
case_entry('case-length-string', case(cable=with_cable(length='0.6')), 'cable.length')
case_entry('case-length-nan', case(cable=with_cable(length='NaN')), 'NaN')
case_entry('case-length-overflow', good.replace('"length": 0.6', '"length": 1e999'),
           'not valid JSON')
case_entry('case-length-negative', case(cable=with_cable(length=-0.6)), 'cable.length')
case_entry('case-length-zero', case(cable=with_cable(length=0)), 'cable.length')
case_entry('case-diameter-negative', case(cable=with_cable(diameter=-0.006)), 'cable.diameter')
case_entry('case-stiffness-zero', case(cable=with_cable(bending_stiffness=0)),
           'bending_stiffness')
case_entry('case-density-infinite', case(cable=with_cable(linear_density='Infinity')),
           'linear_density')
case_entry('case-gravity-short', case(extra={'gravity': [0, -9.81]}), 'gravity')
case_entry('case-gravity-null', case(extra={'gravity': None}), 'gravity')
clamp0 = {'s': 0.0, 'position': [0, 0, 0], 'tangent': [1, 0, 0], 'normal': [0, 0, 1]}
clamp1 = {'s': 0.6, 'position': [0.45, 0, 0], 'tangent': [1, 0, 0], 'normal': [0, 0, 1]}
case_entry('case-clamp-s-negative', case(clamps=[dict(clamp0, s=-0.1), clamp1]), 'clamps[0].s')
case_entry('case-clamp-s-beyond-length', case(clamps=[clamp0, dict(clamp1, s=0.9)]),
           'clamps[1].s')
case_entry('case-clamp-position-text', case(clamps=[clamp0, dict(clamp1, position='here')]),
           'clamps[1].position')
case_entry('case-clamps-unordered', case(clamps=[dict(clamp1), dict(clamp0)]), 'clamps[')
case_entry('case-clamp-tangent-zero', case(clamps=[clamp0, dict(clamp1, tangent=[0, 0, 0])]),
           'tangent')
case_entry('case-clamp-normal-parallel',
           case(clamps=[clamp0, dict(clamp1, normal=[1, 0, 0])]), 'clamps[1]')
case_entry('case-clamps-too-far-apart',
           case(clamps=[clamp0, dict(clamp1, position=[2.0, 0, 0])]), 'apart but only')
case_entry('case-clamp-kind-unknown', case(clamps=[clamp0, dict(clamp1, kind='glue')]),
           "'glue' is unknown")
case_entry('case-recording-missing', case(), "not found", files={})
case_entry('case-recording-kind-unknown',
           case(recordings=[{'kind': 'xray', 'file': 'centerline.csv'}]), "'xray' is unknown")
case_entry('case-recordings-empty', case(recordings=[]), 'recordings')
case_entry('case-recording-is-folder', case(recordings=[{'kind': 'centerline', 'file': 'sub'}]),
           'not found', files={'sub/placeholder.txt': 'a folder, not a CSV\n'})
case_entry('case-name-missing', json.dumps({k: v for k, v in json.loads(good).items()
                                            if k != 'name'}), 'name')
case_entry('case-force-test-missing',
           case(recordings=[{'kind': 'force_curve', 'file': 'bending.csv'}]), 'test',
           files={'bending.csv': 'step,displacement,force\n0,0,0\n1,0.001,0.1\n'})
case_entry('case-invalid-utf8', good.replace('"bad"', '"b\xffd"').encode('latin-1'),
           'not valid JSON')
case_entry('case-deeply-nested', '[' * 200000 + ']' * 200000, 'must be a JSON object')
case_entry('case-simulate-nan-gravity', case(extra={'gravity': [0, 0, 'nan']}), 'gravity',
           command='simulate')
case_entry('case-simulate-length-zero', case(cable=with_cable(length=0)), 'cable.length',
           command='simulate')

# folders and paths
write('case/case-json-is-folder/case.json/placeholder.txt', 'case.json is a folder here\n')
entry('case-json-is-folder', 'diagnose case/case-json-is-folder/case.json --out {out}', 2,
      'case/case-json-is-folder/case.json', 'holds no case.json')
entry('case-no-such-path', 'diagnose case/does-not-exist --out {out}', 2,
      'case/does-not-exist', 'no such file')
write('case/case-folder-without-case/placeholder.txt', 'no case.json in this folder\n')
entry('case-folder-without-case', 'diagnose case/case-folder-without-case --out {out}', 2,
      'case/case-folder-without-case', 'no case')
for sub in ('a', 'b'):
    # The same name twice; both also lack their recording, so the batch has nothing to run.
    write('case/case-duplicate-names/%s/case.json' % sub, case(name='twin'))
entry('case-duplicate-names', 'diagnose case/case-duplicate-names --out {out}', 2,
      'case/case-duplicate-names/b/case.json', "duplicate case name 'twin'")
os.makedirs(os.path.join(HERE, 'case/case-dangling-link'), exist_ok=True)
link = os.path.join(HERE, 'case/case-dangling-link/case.json')
if os.path.lexists(link):
    os.remove(link)
os.symlink('nowhere/case.json', link)
entry('case-dangling-link', 'diagnose case/case-dangling-link/case.json --out {out}', 2,
      'case/case-dangling-link/case.json', 'symbolic link that leads nowhere')
entry('case-fifo', 'diagnose case/case-fifo/case.json --out {out}', 2,
      'case/case-fifo/case.json', 'not a regular file', setup='fifo:case/case-fifo/case.json')
entry('case-huge-json', 'diagnose case/case-huge/case.json --out {out}', 2,
      'case/case-huge/case.json', 'more than the limit',
      setup='sparse:case/case-huge/case.json:100000000')
write('case/case-fifo/.keep', '')
write('case/case-huge/.keep', '')

# ---------------------------------------------------------------- centreline CSV ----------
def csv_entry(id_, text, message):
    case_entry(id_, case(), message, names='centerline.csv', files={'centerline.csv': text})


csv_entry('csv-empty', '', 'empty')
csv_entry('csv-header-only', 's,x,y,z\n', 'at least 2')
csv_entry('csv-missing-column', 's,x,y\n0,0,0\n0.6,0.45,0\n', "missing column 'z'")
csv_entry('csv-ragged-row', 's,x,y,z\n0,0,0,0\n0.3,0.2,0\n0.6,0.45,0,0\n', 'line 3 has 3 cells')
csv_entry('csv-nan-cell', 's,x,y,z\n0,0,0,0\n0.3,nan,0,0\n0.6,0.45,0,0\n', 'NaN')
csv_entry('csv-inf-cell', 's,x,y,z\n0,0,0,0\n0.3,0.2,-inf,0\n0.6,0.45,0,0\n', 'infinite')
csv_entry('csv-text-cell', 's,x,y,z\n0,0,0,0\n0.3,0.2,zero,0\n0.6,0.45,0,0\n', "not a number")
csv_entry('csv-empty-cell', 's,x,y,z\n0,0,0,0\n0.3,,0,0\n0.6,0.45,0,0\n', 'is empty')
csv_entry('csv-s-partial', 's,x,y,z\n0,0,0,0\n,0.2,0,0\n0.6,0.45,0,0\n', "column 's'")
csv_entry('csv-s-decreasing', 's,x,y,z\n0,0,0,0\n0.4,0.2,0,0\n0.3,0.45,0,0\n', 'decreas')
csv_entry('csv-one-point', 's,x,y,z\n0,0,0,0\n', 'at least 2')
csv_entry('csv-binary-garbage', bytes(range(256)) * 4, 'line')
case_entry('csv-huge', case(), 'more than the limit', names='centerline.csv', files={})
rows[-1] = rows[-1][:1] + ('sparse:case/csv-huge/centerline.csv:3000000000',) + rows[-1][2:]

case_entry('case-recording-absolute',
           case(recordings=[{'kind': 'centerline', 'file': '/etc/passwd'}]), 'is absolute')
case_entry('case-recording-leaves-folder',
           case(recordings=[{'kind': 'centerline', 'file': '../case-recording-absolute/case.json'}]),
           'leaves the case folder')
case_entry('case-duplicate-key', good.replace('"name": "bad"', '"name": "bad", "name": "worse"'),
           'appears twice')
case_entry('case-scan-and-force',
           case(recordings=[{'kind': 'centerline', 'file': 'centerline.csv'},
                            {'kind': 'force_curve', 'file': 'bending.csv',
                             'test': {'type': 'pinned_bending', 'prebend': 0.0,
                                      'max_displacement': 0.05}}]),
           'two cases', files={'centerline.csv': CENTERLINE,
                               'bending.csv': 'step,displacement,force\n0,0,0\n1,0.001,0.1\n'})
case_entry('case-torsion-with-bending-columns',
           case(recordings=[{'kind': 'force_curve', 'file': 'torsion.csv',
                             'test': {'type': 'clamped_torsion', 'max_angle': 0.2}}]),
           'clamped_torsion', names='torsion.csv',
           files={'torsion.csv': 'step,displacement,force\n0,0,0\n1,0.001,0.1\n2,0.002,0.2\n'})

# ---------------------------------------------------------------- force-curve CSV ---------
FORCE_REC = [{'kind': 'force_curve', 'file': 'bending.csv',
              'test': {'type': 'pinned_bending', 'prebend': 0.0, 'max_displacement': 0.05}}]


def force_entry(id_, text, message):
    case_entry(id_, case(recordings=FORCE_REC), message, names='bending.csv',
               files={'bending.csv': text})


force_entry('force-wrong-columns', 'step,a,b\n0,0,0\n1,1,1\n', 'column')
force_entry('force-step-not-integer', 'step,displacement,force\n0,0,0\n1.5,0.01,0.1\n', 'step')
force_entry('force-one-row', 'step,displacement,force\n0,0,0\n', '2')
force_entry('force-nan', 'step,displacement,force\n0,0,0\n1,0.01,NaN\n', 'NaN')

# ---------------------------------------------------------------- PLY scans ----------------
SCAN_REC = [{'kind': 'scan', 'file': 'scan.ply'}]


def ply_header(fmt, n, prop='float', extra=''):
    return ('ply\nformat %s 1.0\nelement vertex %s\nproperty %s x\nproperty %s y\n'
            'property %s z\n%send_header\n' % (fmt, n, prop, prop, prop, extra))


def ply_entry(id_, data, message):
    case_entry(id_, case(recordings=SCAN_REC), message, names='scan.ply',
               files={'scan.ply': data})


pts = b''.join(struct.pack('<3f', 0.45 * i / 9, 0, 0) for i in range(10))
ply_entry('ply-not-ply', 'solid tube\nfacet normal 0 0 1\n', 'not a PLY file')
ply_entry('ply-ascii-claims-1e12-points', ply_header('ascii', 10 ** 12) + '0 0 0\n1 1 1\n',
          'header declares 1000000000000')
ply_entry('ply-binary-claims-1e12-points',
          ply_header('binary_little_endian', 10 ** 12).encode() + pts,
          'header declares 1000000000000')
ply_entry('ply-truncated-binary', ply_header('binary_little_endian', 10).encode() + pts[:-7],
          'truncated')
ply_entry('ply-no-end-header', ply_header('ascii', 2).replace('end_header\n', '') + '0 0 0\n',
          'end_header')
ply_entry('ply-unknown-format', ply_header('binary_middle_endian', 2) + '0 0 0\n1 1 1\n',
          'unknown format')
ply_entry('ply-no-vertex-element',
          'ply\nformat ascii 1.0\nelement point 1\nproperty float x\nend_header\n0\n',
          "no 'vertex' element")
ply_entry('ply-missing-z',
          'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n'
          'end_header\n0 0\n', "no property 'z'")
ply_entry('ply-int-coordinates', ply_header('ascii', 2, 'int') + '0 0 0\n1 1 1\n',
          'must be float or double')
ply_entry('ply-nan-vertex', ply_header('ascii', 2) + '0 0 0\nnan 1 1\n', 'non-finite')
ply_entry('ply-negative-count', ply_header('ascii', -5) + '0 0 0\n', 'malformed element line')
ply_entry('ply-list-length-huge',
          ply_header('binary_little_endian', 1, extra='property list uint int idx\n').encode()
          + struct.pack('<3fI', 0, 0, 0, 4000000000), 'list length')
ply_entry('ply-huge-file', b'', 'more than the limit')
rows[-1] = rows[-1][:1] + ('sparse:case/ply-huge-file/scan.ply:2147483649',) + rows[-1][2:]
# A 1.5 GB sparse file whose header (written by the test) claims 10^12 points: refused from the
# header and the size, before the body is read.
ply_entry('ply-sparse-1e12-header', b'', 'header declares 1000000000000')
rows[-1] = rows[-1][:1] + ('sparse-ply:case/ply-sparse-1e12-header/scan.ply:1500000000',) + \
    rows[-1][2:]

# ---------------------------------------------------------------- SECTION.json -------------
def section_entry(id_, obj, message):
    rel = 'section/%s/section.json' % id_
    write(rel, obj if isinstance(obj, str) else json.dumps(obj, indent=1))
    entry(id_, 'section ' + rel, 2, rel, message)


wire = {'name': 'w', 'outer_radius': 0.0005, 'material': 'cu', 'position': [0, 0]}
cu = {'cu': {'E': 1.1e11, 'nu': 0.34, 'density': 8900}}
section_entry('section-empty-components',
              {'format': 'cablefit-section/1', 'materials': cu, 'components': []}, 'is empty')
section_entry('section-unknown-key', {'format': 'cablefit-section/1', 'materials': cu,
                                      'components': [wire], 'colour': 'red'}, 'colour')
section_entry('section-nu-out-of-range',
              {'format': 'cablefit-section/1', 'materials': {'cu': {'E': 1e11, 'nu': 0.7,
                                                                    'density': 8900}},
               'components': [wire]}, 'nu')
section_entry('section-library-missing', {'format': 'cablefit-section/1',
                                          'library': 'nowhere.json', 'components': [wire]},
              'no such file')
rows[-1] = rows[-1][:3] + ('section/section-library-missing/nowhere.json',) + rows[-1][4:]
section_entry('section-torsion-cells-huge',
              {'format': 'cablefit-section/1', 'materials': cu, 'components': [wire],
               'torsion': {'finest_cells': 1000000000, 'levels': 2}}, 'finest_cells must be <= 1024')
section_entry('section-position-huge',
              {'format': 'cablefit-section/1', 'materials': cu,
               'components': [dict(wire, position=[0, 1e308])]}, 'from the section')
section_entry('section-modulus-huge',
              {'format': 'cablefit-section/1',
               'materials': {'cu': {'E': 1e300, 'nu': 0.34, 'density': 8900}},
               'components': [wire]}, 'at most')
section_entry('section-truncated', '{"format": "cablefit-section/1", "components": [{"na',
              'not valid JSON')

# ---------------------------------------------------------------- harness.json (relax) -----
STL = '{samples}/harness/bent_tubes.stl'


def harness_entry(id_, obj, message, names=None):
    rel = 'harness/%s/harness.json' % id_
    write(rel, obj if isinstance(obj, str) else json.dumps(obj, indent=1))
    entry(id_, 'relax ' + STL + ' --config ' + rel + ' --out {out}', 2, names or rel, message)


harness_entry('harness-unknown-key', {'format': 'cablefit-harness/1', 'colour': 1}, 'colour')
harness_entry('harness-gravity-string', {'gravity': 'down'}, 'gravity')
harness_entry('harness-diameter-negative', {'default': {'diameter': -0.01}}, 'diameter')
harness_entry('harness-section-missing',
              {'cables': {'a': {'material': {'section': 'missing.json'}}}}, 'no such file',
              names='harness/harness-section-missing/missing.json')
harness_entry('harness-not-object', '"just a string"', 'object')
harness_entry('harness-duplicate-key', '{"gravity": [0, 0, -9.81], "gravity": [0, 0, 9.81]}',
              'appears twice')
_hinge = {'axis': [0, 0, 1], 'point': [0, 0, 0], 'angles': [0, 45]}
_moving = [{'cable': 'bent_tubes#1', 'support': 'end'}]
harness_entry('harness-min-clearance-negative', {'default': {'min_clearance': -0.01}},
              'min_clearance')
harness_entry('harness-motion-zero-axis',
              {'motion': {'rotation': dict(_hinge, axis=[0, 0, 0]), 'moving': _moving}},
              'motion.rotation.axis must be a non-zero direction')
harness_entry('harness-motion-steps-negative',
              {'motion': {'rotation': _hinge, 'steps': -4, 'moving': _moving}}, 'motion.steps')
harness_entry('harness-motion-angle-nan',
              '{"motion": {"rotation": {"axis": [0, 0, 1], "point": [0, 0, 0], '
              '"angles": [0, NaN]}, "moving": []}}', 'not valid JSON')

# ---------------------------------------------------------------- CAD and meshes (relax) ---
def cad_entry(id_, name, data, message, exit_code=2):
    rel = 'cad/%s/%s' % (id_, name)
    write(rel, data)
    entry(id_, 'relax ' + rel + ' --out {out}', exit_code, rel, message)


step = open(os.path.join(ROOT, 'samples/harness/legacy_harness.step'), 'rb').read()
iges = open(os.path.join(ROOT, 'samples/harness/legacy_harness.igs'), 'rb').read()
stl = open(os.path.join(ROOT, 'samples/harness/bent_tubes.stl'), 'rb').read()
cad_entry('step-truncated', 'harness.step', step[:20000], 'STEP')
cad_entry('step-garbage', 'harness.step', b'ISO-10303-21;\nHEADER;\n\x00\xff garbage\n', 'STEP')
cad_entry('step-empty', 'harness.step', b'', 'empty')
cad_entry('iges-truncated', 'harness.igs', iges[:8000], 'IGES')
cad_entry('stl-truncated', 'tubes.stl', stl[:20000], 'tubes.stl')
cad_entry('stl-empty', 'tubes.stl', b'', 'tubes.stl')
cad_entry('obj-garbage', 'tubes.obj', b'v 0 0 0\nf 1 2 3 4 5\nv nan nan\n', 'tubes.obj')
cad_entry('unknown-extension', 'tubes.xyz', b'0 0 0\n', 'tubes.xyz')
# A byte-mutated copy of the sample STEP on which OCCT 7.6 itself dereferences a null handle
# (SIGSEGV in StepToGeom::MakeCartesianPoint): caught by reading it first in a child process.
rng = random.Random(1002)
mutant = bytearray(step)
for _ in range(4):
    mutant[rng.randrange(1024, len(mutant))] = rng.randrange(256)
cad_entry('step-crashes-occt', 'harness.step', bytes(mutant), 'crashed on this file')
write('cad/step-huge/.keep', '')
entry('step-huge', 'relax cad/step-huge/harness.step --out {out}', 2, 'cad/step-huge/harness.step',
      'more than the limit', setup='sparse:cad/step-huge/harness.step:300000000')
write('cad/stl-huge/.keep', '')
entry('stl-huge', 'relax cad/stl-huge/tubes.stl --out {out}', 2, 'cad/stl-huge/tubes.stl',
      'more than the limit', setup='sparse:cad/stl-huge/tubes.stl:2200000000')

# ---------------------------------------------------------------- KBL harness files (relax) ---
gearbox = open(os.path.join(ROOT, 'tests/data/kbl/kblxml_2.3sr-1_000971250_ltgs_getriebe_170718.kbl')).read()


def kbl_edit(text, old, new):
    assert old in text, old
    return text.replace(old, new, 1)


cad_entry('kbl-not-xml', 'harness.kbl', b'KBL? no: plain text\n', 'not XML')
cad_entry('kbl-truncated', 'harness.kbl', gearbox[:4000].encode(), 'not XML')
cad_entry('kbl-wrong-root', 'harness.kbl', b'<?xml version="1.0"?>\n<Harness id="h"/>\n',
          'not a KBL_container')
cad_entry('kbl-wrong-version', 'harness.kbl',
          kbl_edit(gearbox, 'KBL2.3/KBLSchema', 'KBL3.0/KBLSchema').encode(), 'only KBL 2.x')
cad_entry('kbl-dangling-point', 'harness.kbl',
          kbl_edit(gearbox, '<Control_points>Cartesian_point_',
                   '<Control_points>Nowhere_1 Cartesian_point_').encode(),
          "reference 'Nowhere_1' names no element")
cad_entry('kbl-dangling-routing', 'harness.kbl',
          kbl_edit(gearbox, '<Segments>Segment_1</Segments>', '<Segments>Segment_9</Segments>').encode(),
          "'Segment_9' names no Segment")
cad_entry('kbl-missing-unit', 'harness.kbl',
          kbl_edit(gearbox, '<Si_unit_name>metre</Si_unit_name>', '').encode(), 'Unit ')
# A node moved off its curve is no bad input: the reader puts the node where its curves meet and
# notes it (tests/formats/kbl: KblFile.InconsistentNodes*).

with open(os.path.join(HERE, 'expected.tsv'), 'w') as f:
    f.write('# id\tsetup\texit\tfile named in the error\tmessage substring\tcablefit arguments\n')
    for r in rows:
        f.write('\t'.join(r) + '\n')
print('%d entries' % len(rows))
