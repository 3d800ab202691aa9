%RFP.NC
; the homing program of the homing manual's example (TF5200 homing, section 2.2)
N10 G74 Z1                 (the quill first)
N15 G01 G90 Z200 F500      (then to a safe height)
N20 G74 X1 Y1 A2 B2 S3     (X and Y together, then A and B, then the spindle)
N30 M30
