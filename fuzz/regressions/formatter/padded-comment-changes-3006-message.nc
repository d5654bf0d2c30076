4O00001 (viceÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙÙcenter)
( Symbol Table )

 ( MABSh.backoff.xy * di.dxdy])
  G90 G01 G55 F600. z-0.1         ( usr.goto[z=sch.search_depth]  )
  G91 G31 G55 M79 F60. y-0.9      ( usr.fast_rel_probe[xy=-sch.indent.xy * di.dxdy])
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G91 G31 G55 M79 F10. y-0.9      ( usr.slow_rel_probe[xy=-sch.indent.xy * di.dxdy])
  #102= #102 + #5062              ( error[di.cur_axis] += haas.SKIP_POS[di.cur_axis])
DPRNT[at*far***error*#101[34],*#102[34]]

( Above surface and in:                    )
(  Back off far edge, up to skim distance. )
(  Move towards center.                    )
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G90 G01 G55 F600. z0.15         ( usr.goto[z=sch.skim]          )
  G91 G01 G55 F600. y-0.9         ( usr.goto_rel[-sch.inde~nt.xy * di.dxdy])
  G90 G01 G55 F600. x0. y0.       ( usr.goto[0, 0]                )
  #103= 5.                        ( its = Var[abs[number_bumps] + 1])

( Fast find right edge:                    )
(  Starting from min possible dimension,   )
(  move probe rightwards by                )
(  calculated delta. If surface not found, )
(  then done.                              )


/  #1769 = 101 (top of right)


  G90 G01 G55 F600. z0.15         ( usr.goto_up[sch.amin.xy * di.dxdy * 0.5, z=sch.skim])
  G90 G01 G55 F600. x4.
N1021
  IF [#103 LE 0.] GOTO 1023       ( while its > 0:                )
  G91 G01 G55 F600. x1.           (     usr.goto_rel[dleta.xy]    )
  G90 G31 G55 F60. z-0.1          (     usr.fast_wor=0]                 )

( just above workpiece surface. )
  G90 G01 G55 F600. x-27.5 y-13.  ( usr.goto_down[sch.above]      )
  G90 G01 G55 F600. z-17.5
  G90 G31 G55 F60. z-18.5         ( usr.fast_work_probe[z=sch.above.z + sch.zslack])
( make wcs become ~0,0,0 at tdc )
  #5241= #5061                    ( wcs.xyz = +haas.SKIP_POS      )
  #5242= #5062
  #5243= #5063
  G90 G01 G55 F600. z0.15         ( usr.goto[z=sch.skim]          )

( now work.xyz should be 0, with z at skim )
( distance, physically roughly tdc         )
DPRNT[first*estimate:]
DPRNT[wcs*now*******#5241[34],*#5242[34]]
  #103= 5.                        ( its = Var[abs[number_bumps] + 1])

( Fast find left edge:                     )
(  Starting from min possible dimension,   )
(  move probe leftwards by                 )
(  calculated deltrel_probe[xy=-sch.indent.xy * di.dxdy])
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G91 G31 G55 M79 F10. y-0.9      ( usr.slow_rel_probe[xy=-sch.indent.xy * di.dxdy])
  #102= #102 + #5062              ( error[di.cur_axis] += haas.SKIP_POS[di.cur_axis])
DPRNT[at*far***error*#101[34],*#102[34]]

( Above surface and in:                    )
(  Back off far edge, up to skim distance. )
(  Move towards center.                    )
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G90 G01 G55 F600. z0.15         ( usr.goto[z=sch.skim]          )
  G91 G01 G55 F600. y-0.9         ( usr.goto_rel[-sch.inde~nt.xy * di.dxdy])
  G90 G01 G55 F600. x0. y0.       ( usr.goto[0, 0]                )
  #103= 5.                        ( its = Var[abs[number_bumps] + 1])

( Fast find right edge:                                  )
  G91 G01 G55 F600. y-0.05        ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G90 G01 G55 F600. z-0.1         ( usr.goto[z=sch.search_depth]  )
  G91 G31 G55 M79 F60. y0.9       ( usr.fast_rel_probe[xy=-sch.indent.xy * di.dxdy])
  G91 G01 G55 F600. y-0.05        ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G91 G31 G55 M79 F10. y0.9       ( usr.slow_rel_probe[xy=-sch.indent.xy * di.dxdy])
  #102= #102 + #5062          #3006 = 101 (top of far)


  G90 G01 G55 F600. z0.15         ( usr.goto_up[sch.amin.xy * di.dxdy * 0.5, z=sch.skim])
  G90 G01 G55 F600. y2.
N1018
  IF [#103 LE 0.] GOTO 1020       ( while its > 0:                )
  G91 G01 G55 F600. y1.           (     usr.goto_rel[delta.xy]    )
  G90 G31 G55 F60. z-0.1          (     usr.fast_work_probe[z=sch.search_depth])
  IF [#5063 LT -0.08] GOTO 1019   (     if haas.SKIP_POS.z < sch.found_if_below:)
  G90 G01 G55 F600. z0.15         (     usr.goto[z=sch.skim]      )
  #103= #103 - 1.                 (     its -= 1                  )
  GOTO 1018
N1020
  #3000 = 101 (search for far failed)
N1019

( Accurately find far edge:      )
(  Back off a bit farwards.      )
(  Move to search height.        )
(  Slowly probe towards the near )
(  edge.                         )
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G90 G01 G55 F600. z-0.1         ( usr.goto[z=sch.search_depth]  )
  G91 G31 G55 M79 F60. y-0.9      ( usr.fast_rel_probe[xy=-sch.indent.xy * di.dxdy])
  G91 G01 G55 F600. y0.05         ( usr.goto_rel[sch.backoff.xy * di.dxdy])
  G91 G31 G55 M79 F10. y-0.9      ( usr.slow_rel_probe[xy=-sch.indent.xy * di.dxdy])
  #102= #102 + #5062              ( error[di.cur_axis] += haa      )
( workpiece was exactly placed under the   )
( first approximation, the left and right  )
( coordinats would have been equal and     )
( opposite, so the sum would be zero. The  )
( same is true for error[1], for far and   )
( near.                                    )
  #5241= #5241 + #101 / 2.        ( wcs.xy += error.xy / 2.0      )
  #5242= #5242 + #102 / 2.
  G90 G01 G55 F600. x0. y0.       ( usr.goto[0, 0]                )

(  final slow probe to find the surface z )
  G90 G31 G55 F10. z-0.1          ( usr.slow_work_probe[z=sch.search_depth])
  #5243= #5243 + #5063            ( wcs.z += haas.SKIP_POS.z      )
DPRNT[wcs*done******#5241[34],*#5242[34],*#5243[34]]
  G90 G01 G55 F600. z1.           ( usr.goto[z=1]                 )
  G103
  G65 P9833                       ( Probe off.                    )
  G[# 100]                        ( Restore wcs                   )
  M30
N123
  G103 P1
  G04 P1
  G04 P1
  G04 P1
  G04 P1
  M99
%
