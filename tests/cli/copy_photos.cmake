# Copies only the face photos (A_col.png .. F_col.png) of the sample folder SRC into a fresh folder DST:
# a sample of photos alone, without ring images or traces.
# cmake -DSRC=folder -DDST=folder -P copy_photos.cmake
file(REMOVE_RECURSE "${DST}")
file(MAKE_DIRECTORY "${DST}")
foreach(face A B C D E F)
  if(NOT EXISTS "${SRC}/${face}_col.png")
    message(FATAL_ERROR "${SRC}/${face}_col.png is missing")
  endif()
  file(COPY "${SRC}/${face}_col.png" DESTINATION "${DST}")
endforeach()
