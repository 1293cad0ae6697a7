// Runs inside the module before main (emcc --pre-js; issue 29).
// 1. The URL's query is the command line: ?lesson=camera_inside:2&continuous gives
//    `--lesson camera_inside:2 --continuous`; `scene=PATH` is the positional scene file.
// 2. The canvas follows the page's size: a resize of the browser window resizes the editor's.
// 3. The config folder (window layout, autosave, lesson progress: ui/session/config_dir.cpp) is
//    kept in the browser's IndexedDB: read back before main, written after each change settles.
// 4. Folders: a glTF whose buffers and textures sit in subfolders opens from its folder, dropped
//    on the page or chosen with File > Open folder... (app/web/index.html's folder input).
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

// ---- 4. Folders -------------------------------------------------------------------------------
// Files dropped or picked one by one arrive side by side (GLFW's drop writes each under its bare
// name), which breaks a glTF's "textures/albedo.png". A folder is written into the in-memory file
// system under a fresh folder of its own, keeping every relative path, and handed to the editor
// (gbl_open_folder, ui/editor/editor_window.cpp), which opens the first .gltf or .glb in it, or else
// the G-buffer in it (a folder with manifest.json and its images, or a `render --out` folder).
var gblFolders = 0;

// list: [{path: 'Duck/textures/a.png', file: File}]; label names the folder in the editor's log;
// unread: the files that could not be listed, each with its reason.
function gblWriteFolder(list, label, unread) {
  var dir = '/folders/' + (++gblFolders);
  FS.mkdirTree(dir);
  return Promise.all(list.map(function (item) {
    return item.file.arrayBuffer().then(function (data) {
      var path = dir + '/' + item.path;
      FS.mkdirTree(path.substring(0, path.lastIndexOf('/')));
      FS.writeFile(path, new Uint8Array(data));
    }, function (error) {
      unread.push(item.path + ' (' + error + ')');
    });
  })).then(function () {
    Module['ccall']('gbl_open_folder', null, ['string', 'string', 'string'], [dir, label, unread.join(', ')]);
  });
}

// The files of an <input webkitdirectory>: each knows its path below the chosen folder's parent.
Module['gblOpenFolderFiles'] = function (files) {
  var list = [];
  for (var i = 0; i < files.length; ++i) list.push({path: files[i].webkitRelativePath || files[i].name, file: files[i]});
  var top = list.length ? list[0].path.split('/')[0] : '';
  gblWriteFolder(list, top ? 'the folder ' + top : 'the chosen folder', []);
};

// A dropped entry and everything below it. A directory reader hands out its entries a batch at a
// time (Chromium: 100), so it is read until it gives none.
function gblCollect(entry, list, unread) {
  if (entry.isFile) {
    return new Promise(function (done) {
      entry.file(function (file) {
        list.push({path: entry.fullPath.replace(/^\/+/, ''), file: file});
        done();
      }, function (error) {
        unread.push(entry.fullPath + ' (' + error + ')');
        done();
      });
    });
  }
  var reader = entry.createReader(), below = [];
  return new Promise(function (done) {
    (function more() {
      reader.readEntries(function (entries) {
        if (!entries.length) return Promise.all(below).then(done);
        entries.forEach(function (e) { below.push(gblCollect(e, list, unread)); });
        more();
      }, function (error) {
        unread.push(entry.fullPath + '/ (' + error + ')');
        Promise.all(below).then(done);
      });
    })();
  });
}

// Before GLFW's own drop listener (the canvas's): a drop holding a folder is taken here; files
// alone go on to GLFW as before. Entries must be taken during the event; reading them may wait.
addEventListener('drop', function (event) {
  var items = event.dataTransfer ? event.dataTransfer.items : null;
  if (!items || !Module['calledRun']) return;
  var entries = [], folder = false;
  for (var i = 0; i < items.length; ++i) {
    var entry = items[i].kind === 'file' && items[i].webkitGetAsEntry ? items[i].webkitGetAsEntry() : null;
    if (!entry) continue;
    entries.push(entry);
    if (entry.isDirectory) folder = true;
  }
  if (!folder) return;
  event.preventDefault();
  event.stopPropagation();
  var list = [], unread = [];
  var names = entries.map(function (e) { return e.name; }).join(', ');
  Promise.all(entries.map(function (e) { return gblCollect(e, list, unread); })).then(function () {
    list.sort(function (a, b) { return a.path < b.path ? -1 : a.path > b.path ? 1 : 0; });
    gblWriteFolder(list, (entries.length > 1 ? 'the dropped items ' : 'the folder ') + names, unread);
  });
}, true);

