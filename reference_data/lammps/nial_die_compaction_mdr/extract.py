#!/usr/bin/env python3
"""results.csv of the mdr pressing from its LAMMPS log and data file: each thermo
line (step, time, punch height, punch and floor pressure) and the specimen density,
the particles' solid volume over the die cylinder up to the punch (the measure
tamp's die compaction calls density_specimen).
usage: extract.py LOG PARTICLES_DATA DIE_DIAMETER > results.csv"""
import math, sys

log, data, die_d = sys.argv[1], sys.argv[2], float(sys.argv[3])
lines = open(data).read().split("\n")
start = lines.index("Atoms") + 2
solid = 0.0
for line in lines[start:]:
    if not line.strip():
        break
    solid += math.pi / 6 * float(line.split()[2]) ** 3
area = math.pi * (die_d / 2) ** 2
print("step,time,height,punch_pressure,floor_pressure,density_specimen")
log = open(log).read().split("\n")
header = next(k for k, line in enumerate(log) if line.split()[:1] == ["Step"])
for line in log[header + 1:]:
    f = line.split()
    if f[:1] == ["Fix"]:  # fix halt's message before the last thermo line
        continue
    if not f or not f[0].isdigit():
        break
    step, time, height, punch, floor = f[:5]
    print(f"{step},{time},{height},{punch},{floor},{solid / (area * float(height))!r}")
