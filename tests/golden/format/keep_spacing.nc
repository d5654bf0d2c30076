O1000
  G0	x 5  Y2 



g1   X1 (a)  
