# One pinion-on-rack solve of 14k DoFs: about 2.5 s in Release.
set_tests_properties(${_test} PROPERTIES LABELS "contact")
