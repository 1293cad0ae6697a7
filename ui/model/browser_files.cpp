#include "model/browser_files.h"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif

namespace gbl::ui {

#ifdef __EMSCRIPTEN__
bool pickFilesInBrowser() {
    // Module.gblPickFiles is app/web/index.html's: it clicks the page's hidden file input.
    return EM_ASM_INT({
               if (!Module.gblPickFiles) return 0;
               Module.gblPickFiles();
               return 1;
           }) != 0;
}

bool pickFolderInBrowser() {
    // Module.gblPickFolder is app/web/index.html's: it clicks the page's hidden folder input.
    return EM_ASM_INT({
               if (!Module.gblPickFolder) return 0;
               Module.gblPickFolder();
               return 1;
           }) != 0;
}

bool offerDownload(std::string const& path) {
    return EM_ASM_INT(
               {
                   var path = UTF8ToString($0);
                   var data;
                   try {
                       data = FS.readFile(path);
                   } catch (e) {
                       return 0;
                   }
                   var link = document.createElement('a');
                   link.href = URL.createObjectURL(new Blob([data]));
                   link.download = path.split('/').pop();
                   document.body.appendChild(link);
                   link.click();
                   link.remove();
                   setTimeout(
                       function() { URL.revokeObjectURL(link.href); }, 10000);
                   console.log('gbuffer-lab: download offered: ' + link.download + ' (' + data.length + ' bytes)');
                   return 1;
               },
               path.c_str()) != 0;
}
#else
bool pickFilesInBrowser() {
    return false;
}

bool pickFolderInBrowser() {
    return false;
}

bool offerDownload(std::string const&) {
    return false;
}
#endif

}  // namespace gbl::ui
