#!/usr/bin/env python3
# A folder of program files the way shops keep them, for the program index benchmark (index.sh):
#   gen_library.py FOLDER [FILES]   (default 10,000 files)
# Names of every kind (O1234 without extension, 1234.nc, PART-1234.eia, job_1234.txt); most files
# hold one program, every 20th a punch-out of five; 1 to 8 KB of mill blocks each, with a header
# comment, a tool change, G81 holes and a few macro lines. Program numbers are unique, so the index
# holds FILES + 4 * FILES / 20 programs. main.nc calls the last program (M98 P...).
import os, random, sys

folder = sys.argv[1]
files = int(sys.argv[2]) if len(sys.argv) > 2 else 10000
random.seed(12)
os.makedirs(folder, exist_ok=True)
names = ["O{:04d}", "{:04d}.nc", "PART-{:04d}.eia", "job_{}.txt"]

def program(number):
    lines = [f"O{number:04d} (PART {number} - FIXTURE {number % 7})", "G17 G21 G40 G80 G90", f"T{number % 20 + 1} M06",
             "G54 G00 X0. Y0. S2000 M03", "G43 H1 Z50. M08", "#100 = 0"]
    for i in range(random.randint(10, 80)):
        x, y = random.uniform(-100, 100), random.uniform(-100, 100)
        lines.append(f"N{10 * (i + 1)} G01 X{x:.3f} Y{y:.3f} Z-{random.uniform(0, 5):.3f} F{random.randint(100, 900)}.")
    lines += ["G81 G98 X10. Y10. Z-5. R2. F120.", "X20.", "X30.", "G80", "IF [#100 EQ 0] GOTO 900", "N900 G00 Z50. M09", "M99"]
    return "\n".join(lines) + "\n"

number = 1000
for f in range(files):
    count = 5 if f % 20 == 0 else 1
    text = "%\n" + "".join(program(number + k) for k in range(count)) + "%\n"
    with open(os.path.join(folder, names[f % len(names)].format(number)), "w") as out:
        out.write(text)
    number += count
with open(os.path.join(folder, "main.nc"), "w") as out:
    out.write(f"O0001 (MAIN)\nG21 G90\nM98 P{number - 1}\nM30\n")
print(f"{folder}: {files} files, programs O1000-O{number - 1}")
