# What `cmake --install` puts beside the plugin (component "runtime"), with the
# plugin itself at BOUNDPARTICLES_INSTALL_LIBDIR/paraview-X.Y/plugins/BoundParticles/
# (paraview_plugin_build in the top-level CMakeLists.txt):
#
#   LIBDIR/paraview-X.Y/plugins/BoundParticles.plugins.xml  ParaView's plugin configuration file
#   /etc/profile.d/boundparticles.sh       login shells: PV_PLUGIN_CONFIG_FILE names it
#   lib/environment.d/60-boundparticles.conf  the same for desktop sessions (systemd)
#   share/boundparticles/elements/*.vtp    the built-in element shapes (Elements/)
#   DOCDIR/README.md, DOCDIR/docs/         README, user guide, specification, performance
#   DOCDIR/examples/*.py                   the demo scripts (demo/)
#
# Uses _plugin_subdir and BOUNDPARTICLES_INSTALL_LIBDIR from the caller.

# Debian's ParaView loads no plugin of its own accord: PV_PLUGIN_CONFIG_FILE,
# read by every ParaView executable at start (and by `import paraview` in any
# Python), names plugin configuration files whose plugins it then loads. A
# file beside ParaView's executable (bin/paraview.conf) would need no
# environment, but /usr/bin is no place for it and the tests could not keep
# an installed plugin out of a build's; see docs/user-guide.md, Installing.
option(BOUNDPARTICLES_INSTALL_STARTUP
  "Install the login scripts that make ParaView load the installed plugin at start" ON)

set(_config_name "BoundParticles.plugins.xml")
set(BOUNDPARTICLES_PLUGIN_CONFIG_FILE
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/${_plugin_subdir}/${_config_name}")
# The plugin relative to this file (ParaView resolves it from the file's folder).
# Not in the plugin's own folder: PV_PLUGIN_PATH on that folder would read any
# .xml there as a plugin.
file(WRITE "${BOUNDPARTICLES_PLUGIN_CONFIG_FILE}" "<?xml version=\"1.0\"?>
<Plugins>
  <Plugin name=\"BoundParticles\" filename=\"BoundParticles/BoundParticles.so\" auto_load=\"1\"/>
</Plugins>
")
set(_config_destination "${BOUNDPARTICLES_INSTALL_LIBDIR}/${_plugin_subdir}")
install(FILES "${BOUNDPARTICLES_PLUGIN_CONFIG_FILE}"
  DESTINATION "${_config_destination}"
  COMPONENT runtime)

if (BOUNDPARTICLES_INSTALL_STARTUP)
  # Made when installing, for the prefix installed to (`cmake --install
  # --prefix` included): the same build folder installs for /usr/local or,
  # for the Debian package (scripts/package.sh), for /usr. GNUInstallDirs'
  # rule for the configuration folder: /etc under / and /usr, PREFIX/etc
  # elsewhere. systemd's user manager reads PREFIX/lib/environment.d for /usr
  # and /usr/local.
  set(_startup "${CMAKE_CURRENT_BINARY_DIR}/startup")
  install(CODE "
    string(REGEX REPLACE \"/+\$\" \"\" _bp_prefix \"\${CMAKE_INSTALL_PREFIX}\")
    if (_bp_prefix STREQUAL \"\" OR _bp_prefix STREQUAL \"/usr\")
      set(_bp_etc /etc)
    else ()
      set(_bp_etc \"\${_bp_prefix}/etc\")
    endif ()
    set(BOUNDPARTICLES_INSTALLED_CONFIG_FILE
      \"\${_bp_prefix}/${_config_destination}/${_config_name}\")
    configure_file(\"${CMAKE_CURRENT_LIST_DIR}/boundparticles.sh.in\"
      \"${_startup}/boundparticles.sh\" @ONLY)
    configure_file(\"${CMAKE_CURRENT_LIST_DIR}/60-boundparticles.conf.in\"
      \"${_startup}/60-boundparticles.conf\" @ONLY)
    file(INSTALL DESTINATION \"\${_bp_etc}/profile.d\" TYPE FILE
      FILES \"${_startup}/boundparticles.sh\")
    file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/lib/environment.d\" TYPE FILE
      FILES \"${_startup}/60-boundparticles.conf\")
  " COMPONENT runtime)
endif ()

install(FILES
  "${PROJECT_SOURCE_DIR}/README.md"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}"
  COMPONENT runtime)
# The user's documents and every picture they or the README show, kept at
# their paths under docs/ so the links between them hold.
set(_docs user-guide.md engine-specification.md performance.md)
set(_pictures)
foreach (_doc IN ITEMS ../README.md ${_docs})
  file(READ "${PROJECT_SOURCE_DIR}/docs/${_doc}" _text)
  # Link targets "(path.png)", without the "]" before: brackets would hold a
  # CMake list together.
  string(REGEX MATCHALL "\\([^()# ]+\\.(png|jpg|svg)\\)" _links "${_text}")
  foreach (_link IN LISTS _links)
    string(REGEX REPLACE "^\\((docs/)?(.*)\\)$" "\\2" _picture "${_link}")
    list(APPEND _pictures "${_picture}")
  endforeach ()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
    "${PROJECT_SOURCE_DIR}/docs/${_doc}")
endforeach ()
list(REMOVE_DUPLICATES _pictures)
foreach (_file IN LISTS _docs _pictures)
  get_filename_component(_folder "${_file}" DIRECTORY)
  install(FILES "${PROJECT_SOURCE_DIR}/docs/${_file}"
    DESTINATION "${CMAKE_INSTALL_DOCDIR}/docs/${_folder}"
    COMPONENT runtime)
endforeach ()

file(GLOB _demos "${PROJECT_SOURCE_DIR}/demo/*.py")
install(FILES ${_demos}
  DESTINATION "${CMAKE_INSTALL_DOCDIR}/examples"
  COMPONENT runtime)
