�(SOURCE: 002_39253e4befb68b7d.txt, G52/G152 example)
(DIALECT: pcnc-mill)
(EXPECTED: rapid to X20 Y20 Z0 in G54. G52 X5 Y5 sets a local system in which the current point reads X5 Y5 Z20 - no motion. X30 Y30 and Z40 move in the local system - to work X45 Y45 Z40. G152 cancels the local system - the point then reads X45 Y45 Z40 in G54. M2 ends the program.)
(NOTES: in this dialect a semicolon starts a comment that runs to the end of the line. The seed prints X2)
(DIALECT: pcnc-mill)
(EXPECTED: rapid to X20 Y20 Z0 in G54. G52 X5 Y5 sets a local system in which the current point reads X5 Y5 Z20 - no motion. X30 Y30 and Z40 move in the local system - to work X45 Y45 Z40. G152 cancels the local system - the point then reads X45 Y45 Z40 in G54. M2 ends the program.)
(NOTES: in this dialect a semicolon starts a comment that runs to the end of the line. The seed prints X20Y20Z20 with its comment and the G52 block on one line, so that G52 would fall inside the comment - split into separate lines here. The comment line below G52 translates to - tool coordinates X5Y5Z20.)
G0G17G54
X20Y20Z20 ; координаты инструмента X20Y20Z20
G52 X5 Y5 ; установка локальной системы координат
; �0Y20Z20 with its comment and the G52 block on one line, so that G52 would fall inside the comment - split into separate lines here. The comment line below G52 translates to - tool coordinates X5Y5Z20.)
G0G17G54
X20Y20Z20 ; координаты инструмента X20Y20Z20
G52 X5 Y5 ; установка локальной системы координат
; координаты инструмента X5Y5Z20
X30 Y30 ; движение в локальной системе координат
Z40
G152 ; отмена локальной системы координат
M2
