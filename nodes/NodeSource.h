#pragma once
// What each of FIGMENT's node classes defines in its .cpp: Coin's SO_NODE_SOURCE and an
// initClass() that registers the class with Coin once. figment::init(), a derived class's
// initClass() and a program's own call may each ask; the first registers, the others return.

#include <Inventor/elements/SoSubElement.h>
#include <Inventor/nodes/SoSubNode.h>

// Class derives from one of Coin's nodes: Parent (SoGroup) and its name in .iv files ("Group").
#define FIGMENT_NODE_SOURCE(Class, Parent, ParentName) \
  SO_NODE_SOURCE(Class);                               \
  void Class::initClass() {                            \
    if (classTypeId != SoType::badType()) return;      \
    SO_NODE_INIT_CLASS(Class, Parent, ParentName);     \
  }

// As FIGMENT_NODE_SOURCE, with `registerFirst()` called before Class registers: what Class
// needs registered ahead of it (its parent, elements it enables).
#define FIGMENT_NODE_SOURCE_AFTER(Class, Parent, ParentName, registerFirst) \
  SO_NODE_SOURCE(Class);                                                    \
  void Class::initClass() {                                                 \
    if (classTypeId != SoType::badType()) return;                           \
    registerFirst();                                                        \
    SO_NODE_INIT_CLASS(Class, Parent, ParentName);                          \
  }

// Class derives from one of FIGMENT's nodes, Parent, which is registered first.
#define FIGMENT_DERIVED_NODE_SOURCE(Class, Parent) FIGMENT_NODE_SOURCE_AFTER(Class, Parent, #Parent, Parent::initClass)

// An element of the node kit: SO_ELEMENT_SOURCE and an initClass() that registers it once
// and enables it for SoGLRenderAction (include <Inventor/actions/SoGLRenderAction.h>).
#define FIGMENT_ELEMENT_SOURCE(Class)                  \
  SO_ELEMENT_SOURCE(Class);                            \
  void Class::initClass() {                            \
    if (getClassTypeId() != SoType::badType()) return; \
    SO_ELEMENT_INIT_CLASS(Class, inherited);           \
    SO_ENABLE(SoGLRenderAction, Class);                \
  }
