%
O1000 (T)
G0 X1
(comment line)

G1 X2; G1 X3
M30
%
