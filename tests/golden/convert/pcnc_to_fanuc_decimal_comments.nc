(DIALECT: pcnc-mill)
G0 G17 G54 ; work system 1
X20 Y20 Z20 ; rapid
; a comment line
G1 X25.5 Y20 F200
M2
