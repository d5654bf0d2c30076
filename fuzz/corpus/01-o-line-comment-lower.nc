4%
o0021(plate op 1)
g90 g54 g17
m30
%
