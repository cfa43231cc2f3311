// The script of report.html's 3D view: three.js and report_js/viewer.js,
// bundled and minified by esbuild at build time (CMakeLists.txt) from the
// versions report_js/package-lock.json pins.
#ifndef PFDM_REPORT_VIEWER_SCRIPT_H_
#define PFDM_REPORT_VIEWER_SCRIPT_H_

namespace pfdm {

// JavaScript text that may stand inside <script>...</script> (it holds no
// "</script"); it reads the page's <script id="pfdm-scene"> JSON
// (report/report_scene.h) and draws into #pfdm-view3d's canvas.
extern const char kViewerScript[];

}  // namespace pfdm

#endif  // PFDM_REPORT_VIEWER_SCRIPT_H_
