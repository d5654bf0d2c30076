6%
:: PART 17
G00 X20. Z2. ;; approach
G01 Z-15. F.1 ::cut
M30
%
