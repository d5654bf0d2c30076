%
o1000 (lower case comment stays)
n10  g90   g54 g0 x0 y0
   n20 g1 x10.5 y-2 f200   (feed)  


n30 m30
%
