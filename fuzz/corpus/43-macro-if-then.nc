0IF [#1 EQ 1] THEN #2=3
if [#3 ge 2.] then #4 = #4 + 1
