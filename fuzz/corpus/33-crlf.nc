0%
O0002
G00 X10. Z2.
(CR LF)
M30
%
