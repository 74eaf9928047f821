# The target helpers and the layer checks, in one place (docs/architecture.md, "The layers").
#
# gnss_plain_library(NAME SOURCES ... [LINKS ...])
#   a Qt-free library of protocol/: static, position-independent, no moc.
# gnss_qt_library(NAME SOURCES ... [LINKS ...])
#   a library of the Qt side of protocol/ (link, config, corrections, session): moc on for it
#   alone (the top level switches it on for app/ and ui/ later, with qt_standard_project_setup).
# gnss_ui_library(NAME FOLDER UNITS ... [HEADERS ...] LINKS ...)
#   a library of ui/ (FOLDER/<unit>.cpp and .h per unit), its headers included from ui/.
# gnss_check_layers()
#   at the end of configuring: fails when a library that names no vendor links a vendor's, or
#   when a Qt-free library links Qt (the lists below).

function(gnss_plain_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LINKS")
  add_library(${name} STATIC ${arg_SOURCES})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON AUTOMOC OFF AUTOUIC OFF
                                           AUTORCC OFF)
  target_link_libraries(${name} PUBLIC ${arg_LINKS})
  set_property(GLOBAL APPEND PROPERTY GNSS_PLAIN_LIBRARIES ${name})
endfunction()

function(gnss_qt_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;LINKS")
  add_library(${name} STATIC ${arg_SOURCES})
  set_target_properties(${name} PROPERTIES AUTOMOC ON POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(${name} PUBLIC ${arg_LINKS})
endfunction()

# gnss_ui_library(NAME FOLDER UNITS ... [HEADERS ...] LINKS ...): one of the libraries below,
# made of FOLDER/<unit>.cpp and FOLDER/<unit>.h for each of UNITS and FOLDER/<header>.h for each
# of HEADERS (header only), its headers included by folder from here.
function(gnss_ui_library name folder)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "UNITS;HEADERS;LINKS")
  set(sources)
  foreach(unit IN LISTS arg_UNITS)
    list(APPEND sources ${folder}/${unit}.cpp ${folder}/${unit}.h)
  endforeach()
  foreach(header IN LISTS arg_HEADERS)
    list(APPEND sources ${folder}/${header}.h)
  endforeach()
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/ui)
  target_link_libraries(${name} PUBLIC ${arg_LINKS})
endfunction()

# The targets that hold a receiver family (its record, or its simulated receiver) or list them
# all: only the applications, the catalog tool and the tests link these.
set(GNSS_VENDOR_TARGETS
  gnss_nvs gnss_geostar gnss_nemerix
  gnss_nvs_sim gnss_geostar_sim gnss_nemerix_sim gnss_nmea_sim
  gnss_dialects gnss_simulators gnss_protocol)

# Every library below the applications names no vendor. (gnss_sim, the simulators' common
# base, names none either: each family's simulated receiver is its own target.)
set(GNSS_VENDOR_FREE_LIBRARIES
  gnss_core gnss_rtcm_framing gnss_nmea gnss_state gnss_rtcm gnss_sim gnss_logview gnss_ntrip gnss_compare
  gnss_sites gnss_sites_store
  gnss_qualify gnss_link gnss_config gnss_corrections gnss_serve gnss_session gnss_qualify_campaign
  gnss_qualify_report
  gnss_ui gnss_ui_style gnss_ui_models gnss_ui_widgets gnss_ui_views gnss_ui_settings gnss_ui_qualify
  gnss_ui_logview gnss_app_common gnss_schema_catalog)

# Everything `target` links, directly or through others (targets only, each once).
function(gnss_link_closure target out)
  set(seen)
  set(todo ${target})
  while(todo)
    list(POP_FRONT todo t)
    if(NOT TARGET ${t} OR t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(type ${t} TYPE)
    set(links)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct ${t} LINK_LIBRARIES)
      if(direct)
        list(APPEND links ${direct})
      endif()
    endif()
    get_target_property(iface ${t} INTERFACE_LINK_LIBRARIES)
    if(iface)
      list(APPEND links ${iface})
    endif()
    foreach(l IN LISTS links)
      # $<LINK_ONLY:X> (a static library's private link) is still a link.
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" l "${l}")
      if(TARGET ${l})
        get_target_property(aliased ${l} ALIASED_TARGET)
        if(aliased)
          set(l ${aliased})
        endif()
        list(APPEND todo ${l})
      endif()
    endforeach()
  endwhile()
  list(REMOVE_ITEM seen ${target})
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

function(gnss_check_layers)
  set(problems)
  foreach(lib IN LISTS GNSS_VENDOR_FREE_LIBRARIES)
    if(NOT TARGET ${lib})
      continue()
    endif()
    gnss_link_closure(${lib} closure)
    foreach(v IN LISTS GNSS_VENDOR_TARGETS)
      if(v IN_LIST closure)
        list(APPEND problems "${lib} names no vendor but links ${v}")
      endif()
    endforeach()
  endforeach()
  get_property(plain GLOBAL PROPERTY GNSS_PLAIN_LIBRARIES)
  foreach(lib IN LISTS plain)
    gnss_link_closure(${lib} closure)
    foreach(l IN LISTS closure)
      if(l MATCHES "^Qt[0-9]*::")
        list(APPEND problems "${lib} is Qt-free but links ${l}")
      endif()
    endforeach()
    get_target_property(moc ${lib} AUTOMOC)
    if(moc)
      list(APPEND problems "${lib} is Qt-free but has moc on")
    endif()
  endforeach()
  if(problems)
    list(JOIN problems "\n  " text)
    message(FATAL_ERROR "The layers are broken (docs/architecture.md):\n  ${text}")
  endif()
endfunction()
