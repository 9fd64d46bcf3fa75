# libglvnd's EGL vendor file for Pineda: cmake -DLIBRARY=PATH -DOUTPUT=FILE -P egl_vendor_json.cmake
# (or include() with LIBRARY and OUTPUT set). The library is named by absolute path, so that
# __EGL_VENDOR_LIBRARY_FILENAMES=FILE alone selects Pineda, whatever the library path.
file(WRITE "${OUTPUT}" "{
    \"file_format_version\" : \"1.0.0\",
    \"ICD\" : {
        \"library_path\" : \"${LIBRARY}\"
    }
}
")
