# dggvtp's mesh loader (cli/include/dggvtp), shared by the programs, their fuzz target and the
# benchmarks; fast_float reads the numbers of the text formats. Included by each directory whose
# targets use it, so that FastFloat is searched for only where it is needed and seen there.
find_package(FastFloat REQUIRED)
if(NOT TARGET dggvtp_loader)
  add_library(dggvtp_loader INTERFACE)
  target_include_directories(dggvtp_loader INTERFACE ${PROJECT_SOURCE_DIR}/cli/include)
  target_link_libraries(dggvtp_loader INTERFACE CGAL::DGG_VTP_3 FastFloat::fast_float)
endif()
