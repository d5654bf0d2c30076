7%
O1000 ; part
T1 M06 ; drill
G00 X1,5 Y2.
%
