7G00 X0 Y0 ; rapid home
; whole line
G01 Z-1 F200;no space
