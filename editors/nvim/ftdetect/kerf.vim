" G-code file types for kerf (also set by require('kerf').setup()).
autocmd BufRead,BufNewFile *.nc,*.NC,*.ngc,*.NGC,*.tap,*.TAP,*.cnc,*.CNC,*.mpf,*.MPF,*.eia,*.EIA,O[0-9][0-9][0-9][0-9] setfiletype gcode
