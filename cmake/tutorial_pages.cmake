## Run by the 'doc' target (cmake -DSOURCE_DIR=... -DOUTPUT_DIR=... -P):
## writes one Doxygen page per tutorial, examples/step-N ->
## OUTPUT_DIR/step-N.dox, made of doc/intro.dox, the program
## (@include, found through EXAMPLE_PATH) and doc/results.dox, as deal.II's
## tutorial pages are.
file(GLOB _steps ${SOURCE_DIR}/examples/step-*)
file(MAKE_DIRECTORY ${OUTPUT_DIR})
set(_list "")
foreach(_dir ${_steps})
  get_filename_component(_step ${_dir} NAME)
  string(REPLACE "-" "_" _label ${_step})
  set(_intro "")
  set(_results "")
  if(EXISTS ${_dir}/doc/intro.dox)
    file(READ ${_dir}/doc/intro.dox _intro)
  endif()
  if(EXISTS ${_dir}/doc/results.dox)
    file(READ ${_dir}/doc/results.dox _results)
  endif()
  # anchors are global in Doxygen: prefix them with the tutorial's name
  string(REGEX REPLACE "<a name=\"([A-Za-z0-9_]+)\"></a>" "<a name=\"${_label}_\\1\"></a>" _intro "${_intro}")
  string(REGEX REPLACE "<a name=\"([A-Za-z0-9_]+)\"></a>" "<a name=\"${_label}_\\1\"></a>" _results "${_results}")
  # the first comment line of the program names the tutorial
  file(STRINGS ${_dir}/${_step}.cc _title REGEX "^// ${_step}: " LIMIT_COUNT 1)
  string(REGEX REPLACE "^// ${_step}: *" "" _title "${_title}")
  string(REGEX REPLACE "\\.$" "" _title "${_title}")
  file(WRITE ${OUTPUT_DIR}/${_step}.dox
    "/**\n@page ${_label} The ${_step} tutorial program: ${_title}\n\n"
    "@tableofcontents\n\n${_intro}\n\n<a name=\"${_label}_CommProg\"></a>\n<h1>The commented program</h1>\n\n"
    "@include ${_step}/${_step}.cc\n\n${_results}\n*/\n")
  string(APPEND _list "- @subpage ${_label}\n")
endforeach()
file(WRITE ${OUTPUT_DIR}/tutorials.dox
  "/**\n@page tutorials Tutorial programs\n\nThe tutorials, each with its introduction, "
  "the program and its results:\n\n${_list}\n*/\n")
