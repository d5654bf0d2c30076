(DIALECT: adv400-mill)
::LOOP.NC calls program 12 100 times
;;second header line
G04X1
M98 P12 L100
G04X2
M30
