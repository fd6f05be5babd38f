// load_worker.cpp - idview-load-worker: a helper process of idview's CAD loads (scene/cad/
// cad_session.h). It reads, translates and meshes what the parent sends on file descriptor 3
// (a piece of a split STEP file, its skeleton, or a whole file) and answers there; it dies with
// the thread that started it. Not meant to be run by hand.
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "scene/cad/cad_worker.h"
#include "util/worker_pool.h"

int main(int argc, char** argv) {
    struct stat socket;
    if (argc > 1 || fstat(util::kWorkerFd, &socket) != 0 || !S_ISSOCK(socket.st_mode)) {
        std::fprintf(stderr,
                     "idview-load-worker: a helper of idview's CAD loads, started by idview "
                     "with a socket on file descriptor 3; not meant to be run by hand\n");
        return 2;
    }
    util::workerStarted();
    return scene::cad::runLoadWorker(util::kWorkerFd);
}
