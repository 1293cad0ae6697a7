// Runs inside the module before main (emcc --pre-js; issue 29).
// 1. The URL's query is the command line: ?lesson=camera_inside:2&continuous gives
//    `--lesson camera_inside:2 --continuous`; `scene=PATH` is the positional scene file.
// 2. The canvas follows the page's size: a resize of the browser window resizes the editor's.
// 3. The config folder (window layout, autosave, lesson progress: ui/session/config_dir.cpp) is
//    kept in the browser's IndexedDB: read back before main, written after each change settles.
Module['arguments'] = Module['arguments'] || [];
(function () {
  var query = new URLSearchParams(typeof location !== 'undefined' ? location.search : '');
  query.forEach(function (value, key) {
    if (key === 'scene') { Module['arguments'].push(value); return; }
    Module['arguments'].push('--' + key);
    if (value !== '') Module['arguments'].push(value);
  });
})();

Module['preRun'] = Module['preRun'] || [];
Module['preRun'].push(function () {
  var config = '/home/web_user/.config';
  FS.mkdirTree(config);
  FS.mount(IDBFS, {}, config);
  addRunDependency('gbl-config');
  var saving = true;  // no write before the first read has finished
  FS.syncfs(true, function (error) {
    if (error) console.warn('gbuffer-lab: the saved layout and autosave could not be read from the browser storage: ' + error);
    saving = false;
    removeRunDependency('gbl-config');
  });
  // Written back every 2 s, and when the page is hidden or closed.
  function save() {
    if (saving) return;
    saving = true;
    FS.syncfs(false, function (error) {
      saving = false;
      if (error) console.warn('gbuffer-lab: the browser storage could not be written: ' + error);
    });
  }
  setInterval(save, 2000);
  addEventListener('pagehide', save);
  document.addEventListener('visibilitychange', function () { if (document.hidden) save(); });
});

addEventListener('resize', function () {
  if (Module['calledRun']) Browser.setCanvasSize(innerWidth, innerHeight);
});
