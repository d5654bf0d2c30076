5:: tool change
T1 M6 :: drill
G00 X0 Y0 ;; rapid
;; the end
