# A membrane law no registry holds ('Membrane law' is chosen by name from the program's
# MembraneLawRegistry, elasticity/MembraneLawChoice.hpp): each app refuses it at start-up with
# exit code 2, naming the full key, the registered laws and the closest one, and writes nothing.
capsula_add_refusal_test(reliability_unknown_membrane_law_cell3d
  MATCHES "'Cells/Cell 0/Membrane law' = \"Skalk\" is invalid: it must be one of: NeoHookean, Skalak \\(did you mean \"Skalak\"\\?\\)"
  COMMAND ${_demo} --set "Cells/Cell 0/Membrane law=Skalk")
capsula_add_refusal_test(reliability_unknown_membrane_law_twocell3d
  MATCHES "'Cells/Cell 1/Membrane law' = \"neoHookean\" is invalid: it must be one of: NeoHookean, Skalak \\(did you mean \"NeoHookean\"\\?\\)"
  COMMAND $<TARGET_FILE:twocell3d> ${_decks}/twocell3d/demo.xml ${_level1} --set "Time integration/End time=0.01"
          --set "Cells/Cell 1/Mesh level=1" --set "Cells/Cell 1/Membrane law=neoHookean")
capsula_add_refusal_test(reliability_unknown_membrane_law_tether2d
  MATCHES "'Cell/Membrane law' = \"Hooke\" is invalid: it must be one of: Hookean \\(did you mean \"Hookean\"\\?\\)"
  COMMAND ${_tether2d} --set "Cell/Membrane law=Hooke")
