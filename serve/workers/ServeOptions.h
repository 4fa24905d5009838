#pragma once
// How figment-serve runs: its command line's values (serve/main.cpp), plain data.

#include <string>

namespace figment::serve {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;                     // 0: any free port (the one taken is printed)
  int workers = 1;                     // worker processes; 0: none, every render refused (503)
  int queue = 0;                       // requests waiting at most; 0: four per worker
  double timeLimit = 60;               // s per render
  std::string cacheFolder;             // drapes kept on disk; "" for none
  std::string scenesFolder;            // the body and patterns
  size_t imageCacheBytes = 64u << 20;  // rendered images kept in memory
  double renderRate = 10;              // renders a second per client (its address); 0: no limit
  double renderBurst = 60;             // renders a client may ask at once
  std::string redisUrl;                // the shared cache (and work queue) in Redis; "" for none
  long redisTtl = 30L * 24 * 3600;     // s an entry stays in Redis unread
  int adviceThreads = 0;               // an advice's sizes draped at once in a worker; 0: one per core
};

}  // namespace figment::serve
