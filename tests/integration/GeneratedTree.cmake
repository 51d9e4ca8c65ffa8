# What every integration project does with the tree `kse generate` wrote into KSE_SOURCE_FOLDER:
# it adds the statechart's OBJECT library and one per activity folder (each generated
# CMakeLists.txt defines one), and puts all their targets into <targets_var>.
function(kse_add_generated_tree model targets_var)
  if(NOT KSE_SOURCE_FOLDER)
    message(FATAL_ERROR "set KSE_SOURCE_FOLDER to the folder ${model} was generated into")
  endif()
  add_subdirectory(${KSE_SOURCE_FOLDER}/statecharts/${model} statechart_${model})
  set(_targets statechart_${model})
  file(GLOB _activities LIST_DIRECTORIES true ${KSE_SOURCE_FOLDER}/activities/*)
  foreach(_dir IN LISTS _activities)
    get_filename_component(_name ${_dir} NAME)
    add_subdirectory(${_dir} activity_${_name})
    list(APPEND _targets activity_${_name})
  endforeach()
  set(${targets_var} ${_targets} PARENT_SCOPE)
endfunction()
