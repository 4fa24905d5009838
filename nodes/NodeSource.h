#pragma once
// What each of FIGMENT's node classes defines in its .cpp: Coin's SO_NODE_SOURCE and an
// initClass() that registers the class with Coin once. figment::init(), a derived class's
// initClass() and a program's own call may each ask; the first registers, the others return.

#include <Inventor/nodes/SoSubNode.h>

// Class derives from one of Coin's nodes: Parent (SoGroup) and its name in .iv files ("Group").
#define FIGMENT_NODE_SOURCE(Class, Parent, ParentName) \
  SO_NODE_SOURCE(Class);                               \
  void Class::initClass() {                            \
    if (classTypeId != SoType::badType()) return;      \
    SO_NODE_INIT_CLASS(Class, Parent, ParentName);     \
  }

// Class derives from one of FIGMENT's nodes, Parent, which is registered first.
#define FIGMENT_DERIVED_NODE_SOURCE(Class, Parent) \
  SO_NODE_SOURCE(Class);                           \
  void Class::initClass() {                        \
    if (classTypeId != SoType::badType()) return;  \
    Parent::initClass();                           \
    SO_NODE_INIT_CLASS(Class, Parent, #Parent);    \
  }
