O0001
#3006 = 101 (top of far)
#3000=1(NO TOOL)
IF[#1 EQ 0] THEN #3000 = 2 (VACANT)
#[3000+#2] = 1 (X)
#100 = 1 (  A NOTE )
M30
