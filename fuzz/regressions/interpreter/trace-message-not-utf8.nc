4%

(DPRNTer start)
DPRNT[FECHA (AAMMDD): #3011]

DPRNT[Cycle start timer: #3021]

DPRNT[Override FEED HOLD control: #3004]

DPRNT[Estimated Feedrate: #5081]

DPRNT[Coolant level: #13013]

DPRNT[SpindlÄ RPM: #3027]
(DPRNTer end)

O2001
N10 G99 G18
N11 G21
N12 G50 S6000
N13 G28 U0. W0.

(PROFILE FINISHING3)
N14 T1111
N15 G54
N16 M8
N17 G99
N18 G97 S1644 M3
N19 G0 X58.1 Z5.4
N20 G50 S5000
N21 G96 S300 M3
N22 G0 Z-32.086
N23 X37.384
N24 G1 X36.828 F0.2
N25 X34. Z-33.5 F0(16
N26 Z-37.327 F0.2
N27 G18 G3 X33.3 Z-37.933 I-0.7
N2û÷ÿÿ8 G1 X21.012 Z-41.48
N29 G2 Z-42.52 I0.3 K-0.52
N30 G1 X33.3 Z-46.067
N31 G3 X34. Z-46.673 I-0.35 K-0.606
N32 G1 Z-50.5
N33 X38.
N34 G0 X5ÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿÿ8.1
N35 Z5.4
N36 G97 S1644 M3

N37 M9
N38 G28 U0. W0.
N39 M30
%