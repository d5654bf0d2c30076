G0 X1(a)
G0 X1   (  b c  ) Y2
