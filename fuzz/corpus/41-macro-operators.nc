2#1=#2 OR #3 XOR #4 AND #5 MOD 3
#6=[#1 EQ 1] AND [#2 NE 0]
#7=-#1
#8=+[#2]
