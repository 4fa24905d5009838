#pragma once
// Coin's messages while the guard reads a scene. Coin reports through handler callbacks, several
// lines per message: a read error becomes the one line that refuses the scene, and warnings wait
// until the read is over, passed on to the program's own handler when it succeeds and dropped
// when it fails (the refusal's one line names the cause; warnings on the way would make it
// several). The handlers are the object's for its life only: it puts back the ones it found, so
// any Coin program (a pivy one included) keeps its own.

#include <Inventor/errors/SoDebugError.h>

#include <string>
#include <vector>

class SoError;

namespace figment::guard {

class ReadMessages {
 public:
  ReadMessages();
  ~ReadMessages();
  ReadMessages(const ReadMessages&) = delete;
  ReadMessages& operator=(const ReadMessages&) = delete;

  // The read errors so far, oldest first, each one line: "line 4: MeshFile 'Body': fileName
  // "nothere.obj" not found", with " (in FILE)" appended when the error lies in another file than
  // `scene`.
  std::vector<std::string> readErrors(const std::string& scene) const;
  // Posts the warnings held so far to the handler found, as Coin posted them, and forgets them.
  void passOnWarnings();

  // Coin's multi-line message as one line: "Coin read error: " dropped, lines joined by "; ".
  static std::string oneLine(const std::string& message);

 private:
  struct ReadError {
    std::string message;
    std::string file;
    int line = 0;
  };
  struct Warning {
    SoDebugError::Severity severity;
    std::string text;  // Coin's whole message: "Coin warning in SoFile::readNamedFile(): ..."
  };
  static void onReadError(const SoError* error, void* self);
  static void onDebugMessage(const SoError* error, void* self);

  std::vector<ReadError> readErrors_;
  std::vector<Warning> warnings_;
  SoErrorCB* readHandler_;
  void* readData_;
  SoErrorCB* debugHandler_;
  void* debugData_;
};

}  // namespace figment::guard
