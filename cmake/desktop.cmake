# desktop.cmake - what makes idview a desktop application, installed beside the program: the
# launcher (.desktop), its icon, the MIME types it opens that shared-mime-info lacks, and the
# thumbnailer that file managers call for previews (data/, docs/desktop.md).
include_guard(GLOBAL)
include(GNUInstallDirs)

set(IDVIEW_DESKTOP_DATA ${CMAKE_CURRENT_LIST_DIR}/../data)
install(FILES ${IDVIEW_DESKTOP_DATA}/idview.desktop
  DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${IDVIEW_DESKTOP_DATA}/idview.svg
  DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${IDVIEW_DESKTOP_DATA}/idview.xml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages)
install(FILES ${IDVIEW_DESKTOP_DATA}/idview.thumbnailer
  DESTINATION ${CMAKE_INSTALL_DATADIR}/thumbnailers)
