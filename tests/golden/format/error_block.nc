g0 x1
  G1 X-12.8. y2
 g0   x3
