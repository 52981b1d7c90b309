# rt_find_oiio.cmake - find OpenImageIO without its CMake package file.
#
# Debian 12's OpenImageIOConfig.cmake (OpenImageIO 2.4) stops configuration
# with an error unless openimageio-tools (it references /usr/bin/iconvert)
# and libopencv-dev (its interface includes /usr/include/opencv4) are both
# installed, neither of which the library needs.  So we look for the header
# and the libraries ourselves, through pkg-config when it is there, and
# define the imported target OpenImageIO::OpenImageIO that the package file
# would have defined.
#
# Sets RT_OIIO_FOUND (TRUE/FALSE).  Include at most once per configuration.
set(RT_OIIO_FOUND FALSE)
if(NOT TARGET OpenImageIO::OpenImageIO)
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_check_modules(RT_OIIO_PC QUIET OpenImageIO>=2.0)
  endif()
  find_path(RT_OIIO_INCLUDE_DIR OpenImageIO/imageio.h HINTS ${RT_OIIO_PC_INCLUDE_DIRS})
  find_library(RT_OIIO_LIBRARY OpenImageIO HINTS ${RT_OIIO_PC_LIBRARY_DIRS})
  find_library(RT_OIIO_UTIL_LIBRARY OpenImageIO_Util HINTS ${RT_OIIO_PC_LIBRARY_DIRS})
  if(RT_OIIO_INCLUDE_DIR AND RT_OIIO_LIBRARY AND RT_OIIO_UTIL_LIBRARY)
    add_library(OpenImageIO::OpenImageIO INTERFACE IMPORTED)
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${RT_OIIO_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${RT_OIIO_LIBRARY};${RT_OIIO_UTIL_LIBRARY}")
    set(RT_OIIO_FOUND TRUE)
  endif()
else()
  set(RT_OIIO_FOUND TRUE)
endif()
