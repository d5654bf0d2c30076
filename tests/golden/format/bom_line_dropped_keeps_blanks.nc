
 /G0 X1.
/ G1 X2.
