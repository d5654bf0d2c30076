4#1=
#=1
IF [#1 GT] GOTO
SIN[
#[#[#[1]]]=[[[2]]]
ATAN[1,
