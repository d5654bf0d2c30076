¥n4O00001 (vicecenter)
( Symbol Table )

 ( MABS_ABOVE_VICE : -27.500,-13.000,-17.500 )
 ( above           : -27.500,-13.000,-17.500 )
 ( amax            :  16.000,  9.000,  3.200 )
 ( amin            :   8.000,  4.000,  1.000 )
 ( backoff     c         )
DPRNT[first*estimate:]
DPRNT[wcs*now*******#5241[34],*#5242[34]]
  #103= 5.                        ( its = Var[abs[number_bumps] + 1])

( Fast find left edge:                     )
(  Starting from min possible dimension,   )
(  move probe leftwards by                 )
(  calculated delta. If surface not found, )
(  then done.                              )


/  #3006 = 101 (top of left)


  G90 G01 G55 F600. z0.15         ( usr.goto_up[sch.amin.xy * di.dxl_probe[xy=-sch.indent.xy * di.dxdy])
  #102= #102 + #5062              ( error[di.cu         )
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G45 G01 G55 F600. z0.15         ( usr.goto[z=sch.skim]          )
  G91 G01 G55 F600. y-0.9         ( usr.goto_rel[-sch.indent.xy * di.dxdy])
  G90 G01 G55 F600. x0. y0.       ( usr.goto[0, 0]                )
  #103= 5.                        ( its = Var[abs[number_bumps] + 1])

( Fast find right edge:                    )
(  Starting from min possible dimension,   )
(  move probe rightwards by                )
(  ci.dxdy])

(]The x coordinates of the left and right  )
( edge have been summed and put into       )
( error[5]. That value is double the error )
( of the first guess, since every bit of   )
( error shifts the apparent locations of   )
( the left and right side [if the          )
( workpiece was exactly placed under the   )
( first approximation, the left and right  )
( coordinats would have been equal and     )
( opposite, so the sum would be zero. The  )
( same is true for error[1], for far and   )
( near.                                    )
  #5241= #5241 + #101 / 2.        ( wcs.xy += error.xy / 2.0      )
  #5242= #5242 + #102 / 2.
  G90 G01 G55 F600. x0. y0.       ( low_work_probe[z=sch.search_depth])
  #5243= #5243 + #5063            ( wcs.z += haas.SKIP_POS.z      )
DPRNT[wcs*done******#5241[34],*#5242[34],*#5243[34]]
  G90 G01 G55 F600. z1.           ( usr.goto[z=1]                 )
  G103
  G65 P9833                       ( Probe off.                    )
  G[# 100]                        ( Restore wcs                   )
  M30
N123
  G101 P1
  G04 P1
  G04 P1
  G04 P1
  G04 P1
  M99
%
